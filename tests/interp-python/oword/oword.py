import interpreter


def area(self, w, h):
    self.calls += 1
    return w * h


def count(self, *args):
    self.calls += 1
    print("count: %d arguments, call level %d" % (len(args), self.call_level))
    self.params["seen"] = len(args)
    self.params["_last_count"] = len(args)


def refuse(self, *args):
    return "refused with %d arguments" % len(args)


def crash(self, *args):
    return 1 / 0


def shadow(self):
    return 42


def odd(self):
    return [1, 2]
