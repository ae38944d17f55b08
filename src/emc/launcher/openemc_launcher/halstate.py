"""halstate: what the launcher asks HAL (through halcmd) while starting and stopping."""


def user_components(children):
    """[(name, pid)] of the user-space components, halcmd's own excluded."""
    status, text = children.output(["halcmd", "-s", "show", "comp"])
    if status != 0:
        return []
    found = []
    for line in text.splitlines():
        col = line.split()
        if len(col) >= 5 and col[1] == "User" and col[3].isdigit():
            if not col[2].startswith("halcmd"):
                found.append((col[2], int(col[3])))
    return found


def component_names(children):
    """Names of every loaded component (realtime and user-space)."""
    status, text = children.output(["halcmd", "-s", "show", "comp"])
    if status != 0:
        return []
    return [line.split()[2] for line in text.splitlines() if len(line.split()) >= 4]


def value(children, name):
    """Value text of a pin or parameter (getp), or None when it does not exist."""
    status, text = children.output(["halcmd", "getp", name])
    return text.strip() if status == 0 else None


def nonzero(text):
    """True when a getp value is a number other than 0 (or TRUE)."""
    if text is None:
        return False
    if text.upper() in ("TRUE", "FALSE"):
        return text.upper() == "TRUE"
    try:
        return float(text) != 0.0
    except ValueError:
        return False
