"""pycomp.py: drives a Python hal component from halcmd and checks values both ways."""
import re

import hal
from pyhal_test import halcmd, show


c = hal.component("pytest")
c.newpin("out", hal.HAL_FLOAT, hal.HAL_OUT)
c.newpin("in", hal.HAL_S32, hal.HAL_IN)
c.newpin("bit-in", hal.HAL_BIT, hal.HAL_IN)
c.newpin("io", hal.HAL_U32, hal.HAL_IO)
c.newpin("big", hal.HAL_S64, hal.HAL_OUT)
c.newpin("ubig", hal.Type.UINT, hal.Dir.OUT)
c.newparam("gain", hal.HAL_FLOAT, hal.HAL_RW)
c.newparam("count", hal.HAL_U32, hal.HAL_RO)
show("exists before ready", lambda: (hal.component_exists("pytest"),
                                    hal.component_is_ready("pytest")))
show("bad pin type", lambda: c.newpin("bad", 99, hal.HAL_IN))
show("bad pin dir", lambda: c.newpin("bad", hal.HAL_BIT, hal.HAL_RO))
show("bad param type", lambda: c.newparam("bad", hal.HAL_PORT, hal.HAL_RW))
show("bad param dir", lambda: c.newparam("bad", hal.HAL_BIT, hal.HAL_IN))
show("long name", lambda: c.newpin("x" * 50, hal.HAL_BIT, hal.HAL_IN))
show("duplicate component", lambda: hal.component("pytest"))
c.ready()
show("exists after ready", lambda: (hal.component_exists("pytest"),
                                   hal.component_is_ready("pytest"),
                                   hal.component_exists("nosuch")))

print("== Python to HAL")
c["out"] = 2.5
c.big = -5000000000
c.ubig = 2 ** 64 - 1
c.count = 9
for name in ("out", "big", "ubig", "count"):
    show("getp pytest." + name, lambda: halcmd("getp", "pytest." + name))

print("== HAL to Python")
halcmd("setp", "pytest.in", "42")
halcmd("setp", "pytest.gain", "0.25")
halcmd("setp", "pytest.io", "4000000000")
show("in gain io", lambda: (c["in"], c.gain, c.io))
show("getpins", lambda: sorted(c.getpins().items()))

print("== signals")
halcmd("net", "fsig", "pytest.out")
show("get_value fsig", lambda: hal.get_value("fsig"))
c.out = 3.75
show("gets fsig", lambda: halcmd("gets", "fsig"))
show("new_sig bsig", lambda: hal.new_sig("bsig", hal.HAL_BIT))
show("new_sig bsig again", lambda: hal.new_sig("bsig", hal.HAL_BIT))
show("new_sig bad type", lambda: hal.new_sig("xsig", 99))
show("connect bit-in", lambda: hal.connect("pytest.bit-in", "bsig"))
halcmd("sets", "bsig", "1")
show("bit-in after sets", lambda: c["bit-in"])
show("set_s bsig 0", lambda: (hal.set_s("bsig", 0), c["bit-in"]))
show("connect type mismatch", lambda: hal.connect("pytest.in", "bsig"))
show("connect unknown pin", lambda: hal.connect("pytest.nosuch", "bsig"))
show("disconnect", lambda: hal.disconnect("pytest.bit-in"))
show("get_s fsig", lambda: hal.get_s("fsig"))
show("get_s nosuch", lambda: hal.get_s("nosuch"))

print("== set_p and get_p")
show("set_p io", lambda: (hal.set_p("pytest.io", "17"), c.io))
show("get_p", lambda: (hal.get_p("pytest.io"), hal.get_p("pytest.gain"), hal.get_p("nosuch")))
show("set_p out", lambda: hal.set_p("pytest.out", "1"))
show("set_p nosuch", lambda: hal.set_p("nosuch", "1"))
show("set_p bad value", lambda: hal.set_p("pytest.io", "abc"))
show("get_value nosuch", lambda: hal.get_value("nosuch"))

print("== conversions")
for value in ("yes", "off", 0.0, 2.5, "2", "maybe", None):
    def setbit(v=value):
        c["bit-in"] = v
        return c["bit-in"]
    show("bit %r" % (value,), setbit)
for value in (-1, 2 ** 32, 1.9, "12", "1.9"):
    def setu32(v=value):
        c.io = v
        return c.io
    show("u32 %r" % (value,), setu32)
show("s32 2**31", lambda: c.__setitem__("in", 2 ** 31))
show("float 'abc'", lambda: c.__setitem__("gain", "abc"))

print("== items and errors")
show("getpin", lambda: (c.getpin("out").get(), c.getpin("out").get_name(),
                        c.getpin("out").get_type(), c.getpin("out").get_dir()))
show("getitem gain", lambda: repr(c.getitem("gain")))
show("getitem bit-in", lambda: repr(c.getitem("bit-in")))
show("getparam out", lambda: c.getparam("out"))
show("missing", lambda: c["nosuch"])
show("duplicate", lambda: c.newpin("in", hal.HAL_S32, hal.HAL_IN))
show("after ready", lambda: c.newpin("late", hal.HAL_S32, hal.HAL_IN))
show("ready twice", lambda: c.ready())
show("len", lambda: len(c))
show("repr", lambda: re.sub(r"\(\d+\)", "(ID)", repr(c)))
c.exit()
show("exists after exit", lambda: (hal.component_exists("pytest"), hal.is_initialized()))
show("access after exit", lambda: c["out"])
show("fsig survives", lambda: hal.get_s("fsig"))
