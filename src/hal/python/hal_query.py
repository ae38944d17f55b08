"""hal_query.py: `hal.query`, dictionaries describing HAL pins, params, signals, comps, functs, threads."""
import _hal

# HAL library component kinds (RT 0, User 1, instance 2) -> hal.CompType values
_COMP_TYPES = {0: 1, 1: 0, 2: 2}


def _halmod():
    """The hal module (imported lazily: hal imports this module)."""
    import hal
    return hal


def _item(raw, haltype):
    """Public dict of a pin or param: `name` is the original name, `alias` the alias; a pin also
    names its signal (None when unlinked), between `alias` and `comp` as LinuxCNC orders them."""
    hal = _halmod()
    aliased = raw["original"] is not None
    info = {"haltype": haltype, "name": raw["original"] if aliased else raw["name"],
            "type": hal.Type(raw["type"]), "dir": hal.Dir(raw["dir"]), "value": raw["value"],
            "alias": raw["name"] if aliased else None}
    if haltype == "pin":
        info["signal"] = raw.get("signal")
    info["comp"] = raw["comp"]
    info["comp_id"] = raw["comp_id"]
    return info


def _pin(raw):
    return _item(raw, "pin")


def _param(raw):
    return _item(raw, "parameter")


def _signal(raw):
    """Public dict of a signal."""
    return {"haltype": "signal", "name": raw["name"], "type": _halmod().Type(raw["type"]),
            "value": raw["value"], "writers": raw["writers"], "readers": raw["readers"],
            "bidirs": raw["bidirs"], "driver": raw["driver"]}


def _comp(raw):
    """Public dict of a component."""
    return {"haltype": "component", "name": raw["name"],
            "type": _halmod().CompType(_COMP_TYPES.get(raw["type"], -1)), "id": raw["id"],
            "pid": raw["pid"], "ready": raw["ready"], "insmod": raw["insmod"]}


def _funct(raw):
    """Public dict of a function."""
    return {"haltype": "function", "name": raw["name"], "comp": raw["comp"],
            "comp_id": raw["comp_id"], "users": raw["users"], "reentrant": raw["reentrant"]}


def _thread(raw):
    """Public dict of a thread; functions numbered from 0, init functs again from 0."""
    functions, counts = [], {False: 0, True: 0}
    for name, is_init in raw["functions"]:
        functions.append({"haltype": "threadfunction", "name": name,
                          "index": counts[is_init], "is_init": is_init})
        counts[is_init] += 1
    return {"haltype": "thread", "name": raw["name"], "comp": raw["comp"],
            "comp_id": raw["comp_id"], "priority": raw["priority"], "period": raw["period"],
            "functions": functions}


def _find(kind, convert, match):
    """First object of kind for which match(raw) is true, converted; else None."""
    for raw in _hal._query(kind):
        if match(raw):
            return convert(raw)
    return None


def _by_name(name):
    """Matcher for the listed name or the original name behind an alias."""
    return lambda raw: name in (raw["name"], raw.get("original"))


def pin(name):
    """Dict describing pin `name` (alias or original), or None."""
    return _find("pin", _pin, _by_name(name))


def param(name):
    """Dict describing parameter `name`, or None."""
    return _find("param", _param, _by_name(name))


def signal(name):
    """Dict describing signal `name`, or None."""
    return _find("signal", _signal, _by_name(name))


def comp(name_or_id):
    """Dict describing a component given by name or id, or None."""
    key = "id" if isinstance(name_or_id, int) else "name"
    return _find("comp", _comp, lambda raw: raw[key] == name_or_id)


def funct(name):
    """Dict describing function `name`, or None."""
    return _find("funct", _funct, _by_name(name))


def thread(name):
    """Dict describing thread `name`, or None."""
    return _find("thread", _thread, _by_name(name))


def _all(kind, convert):
    """Dict name -> description of every object of kind."""
    result = {}
    for raw in _hal._query(kind):
        info = convert(raw)
        result[info["name"]] = info
    return result


def pins():
    return _all("pin", _pin)


def params():
    return _all("param", _param)


def signals():
    return _all("signal", _signal)


def comps():
    return _all("comp", _comp)


def functs():
    return _all("funct", _funct)


def threads():
    return _all("thread", _thread)


def signalpins(sig):
    """Dict pin name -> pin description of every pin linked to signal sig; None when there is
    no such signal."""
    if signal(sig) is None:
        return None
    return {name: info for name, info in pins().items() if info.get("signal") == sig}
