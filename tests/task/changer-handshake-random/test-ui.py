#!/usr/bin/env python3
"""Random changer answered by hand: an empty spindle is tool -1, T0 is a tool in its pocket,
the tool already in the spindle needs neither prepare nor change, G43 H0 means T0."""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from taskui import c, s, say, errors, machine_on, home_all, linuxcnc  # noqa: E402
from changer import io, answer, wait_pin, status, interp_vars, change_to_t0  # noqa: E402


def tlo_z():
    s.poll()
    return round(s.tool_offset[2], 4)


machine_on()
home_all()
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
say("start", status(), "pin", io("tool-number"), "|", interp_vars())
c.mdi("T1")
wait_pin("prepare", True)
say("T1 preparing", status(), "prep", io("tool-prep-number"), io("tool-prep-pocket"))
say("T1 answered", answer("prepare", "prepared"), status(), "|", interp_vars())
c.mdi("M6")
say("M6 answered", answer("change", "changed"), c.wait_complete(), status(),
    "pins", io("tool-number"), io("tool-from-pocket"), "|", interp_vars())
c.mdi("T1")
say("T1 again: prepare asked", wait_pin("prepare", True, 1.0), c.wait_complete(), status(),
    "prep", io("tool-prep-number"), io("tool-prep-pocket"))
c.mdi("M6")
say("M6 of the loaded tool: change asked", wait_pin("change", True, 1.0), c.wait_complete(), status())
change_to_t0()
c.mdi("G43 H0")
say("G43 H0", c.wait_complete(), "tlo z", tlo_z())
c.mdi("G43 H1")
say("G43 H1", c.wait_complete(), "tlo z", tlo_z())
say("errors", errors())
