"""changer: a tool changer the test answers by hand (replaces core_sim's instant loop-back)."""
import os
import time

import hal
import linuxcnc

from taskui import c, e, s, say

PINS = {"prepare": "tool-prepare", "prepared": "tool-prepared",
        "change": "tool-change", "changed": "tool-changed"}

h = hal.component("changer")
h.newpin("prepare", hal.HAL_BIT, hal.HAL_IN)
h.newpin("prepared", hal.HAL_BIT, hal.HAL_OUT)
h.newpin("change", hal.HAL_BIT, hal.HAL_IN)
h.newpin("changed", hal.HAL_BIT, hal.HAL_OUT)
h.ready()
os.system("halcmd delsig tool-prep-loop; halcmd delsig tool-change-loop")
for mine, io in PINS.items():
    os.system("halcmd net changer-%s changer.%s iocontrol.0.%s" % (mine, mine, io))


def io(pin):
    """An iocontrol.0 pin's value."""
    return hal.get_value("iocontrol.0." + pin)


def wait_pin(name, value, timeout=5.0):
    """True once changer.<name> reads value, False after timeout."""
    end = time.time() + timeout
    while time.time() < end:
        if h[name] == value:
            return True
        time.sleep(0.01)
    return False


def answer(request, reply):
    """Wait for the request pin, raise the reply until the request drops; False if none came."""
    if not wait_pin(request, True, 2.0):
        return False
    h[reply] = True
    ok = wait_pin(request, False)
    h[reply] = False
    return ok


def status():
    """Tool fields of the status buffer."""
    time.sleep(0.05)
    s.poll()
    return "spindle %d from %d prepped %d" % (s.tool_in_spindle, s.tool_from_pocket, s.pocket_prepped)


def interp_vars():
    """The interpreter's tool parameters, read with an MDI (debug,) message."""
    while e.poll():
        pass
    c.mdi("(debug,tool #5400 cur #<_current_tool> pocket #<_current_pocket> "
          "sel #<_selected_tool> selpocket #<_selected_pocket>)")
    c.wait_complete()
    end = time.time() + 2
    while time.time() < end:
        m = e.poll()
        if m and m[0] == linuxcnc.OPERATOR_DISPLAY:
            return m[1].strip()
        time.sleep(0.01)
    return "no debug message"


def change_to_t0():
    """T0 then M6, both answered by hand; says what the changer and status show at each step."""
    c.mdi("T0")
    wait_pin("prepare", True)
    say("T0 preparing", status(), "prep", io("tool-prep-number"), io("tool-prep-pocket"))
    answer("prepare", "prepared")
    c.mdi("M6")
    say("T0 M6 answered", answer("change", "changed"), c.wait_complete(), status(),
        "pins", io("tool-number"), io("tool-from-pocket"), "|", interp_vars())
