# bindings.py: exercises every method of the Python ini type (python.md linuxcnc.ini) on config.ini.
import _linuxcnc_ini as linuxcnc

ini = linuxcnc.ini("config.ini")


def show(label, value):
    """Print one labelled result."""
    print("%s: %r" % (label, value))


show("getstring", ini.getstring("EMC", "MACHINE"))
show("getstring num 2", ini.getstring("EMC", "MACHINE", 2))
show("find trailing comment kept", ini.find("EMC", "NUM"))
show("empty value", ini.getstring("EMC", "EMPTY"))
show("missing", ini.getstring("EMC", "NOPE"))
show("missing fallback", ini.getstring("EMC", "NOPE", fallback="fb"))
show("any section", ini.getstring("", "HALFILE", 2))
show("getbool", ini.getbool("EMC", "FLAG"))
show("getbool invalid", ini.getbool("EMC", "BADFLAG"))
show("getbool invalid fallback", ini.getbool("EMC", "BADFLAG", fallback=False))
show("getsint trailing blank", ini.getsint("EMC", "NUM"))
show("getint 3.5", ini.getint("AXIS_X", "MAX_VELOCITY"))
show("getsint hex", ini.getsint("AXIS_X", "HEXV"))
show("getuint -1", ini.getuint("AXIS_X", "NEG"))
show("getreal", ini.getreal("AXIS_X", "MAX_VELOCITY"))
show("getfloat hex", ini.getfloat("AXIS_X", "HEXV"))
show("getreal invalid", ini.getreal("EMC", "MACHINE", fallback=-1.0))
show("getlinearunits", round(ini.getlinearunits("TRAJ", "LINEAR_UNITS"), 9))
show("getangularunits", ini.getangularunits("TRAJ", "ANGULAR_UNITS"))
show("getjointtype", ini.getjointtype("JOINT_0", "TYPE"))
show("maplinearunits mm", ini.maplinearunits("MM"))
show("maplinearunits cm", ini.maplinearunits("cm"))
show("mapangularunits deg", linuxcnc.ini.mapangularunits("deg"))
show("mapjointtype linear", ini.mapjointtype("linear"))
show("mapjointtype bad fallback", ini.mapjointtype("x", fallback=0))
show("hassection", (ini.hassection("HAL"), ini.hassection("hal")))
show("hasvariable", (ini.hasvariable("HAL", "HALFILE", 2), ini.hasvariable("HAL", "HALFILE", 3)))
show("getsections", ini.getsections())
show("getvariables HAL", ini.getvariables("HAL"))
show("getvariables unknown", ini.getvariables("NOPE"))
show("getvariables all count", len(ini.getvariables()))
show("findall", ini.findall("HAL", "HALFILE"))
show("findall section", ini.findall("SUB"))
show("findall section, empty name", ini.findall("SUB", ""))
show("findall any section", ini.findall("", "MACHINE"))
show("findall none", ini.findall("HAL", "NOPE"))
show("lineof", ini.lineof("AXIS_X", "FROM_INCLUDE"))
show("lineof num 2", ini.lineof("EMC", "MACHINE", 2))
show("lineof missing", ini.lineof("EMC", "NOPE"))
for call in (lambda: ini.getstring("EMC", "MACHINE", num=1),
             lambda: ini.getstring("EMC", "MACHINE", 1, "fb")):
    try:
        call()
    except TypeError:
        print("TypeError")
try:
    linuxcnc.ini("/no/such.ini")
except linuxcnc.error as e:
    show("open error", str(e))
try:
    type("Sub", (linuxcnc.ini,), {})
except TypeError:
    print("ini cannot be subclassed")
