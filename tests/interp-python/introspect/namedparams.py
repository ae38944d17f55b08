def _tau(self):
    return 6.2831853


def _tool_diameter(self):
    return self.tool_table[0].diameter


def _broken(self):
    return "namedparams._broken always fails"


def _wrong(self):
    return {"not": "a number"}


def helper_without_underscore(self):
    return 1
