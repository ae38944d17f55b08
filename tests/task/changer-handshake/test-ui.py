#!/usr/bin/env python3
"""Non-random changer answered by hand: prepared pocket shown only once confirmed, T0, a T/M6
of the loaded tool changes nothing, M61 keeps tool-from-pocket, TOOL_CHANGE_POSITION."""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from taskui import c, say, errors, machine_on, home_all, pos, linuxcnc  # noqa: E402
from changer import h, io, answer, wait_pin, status, interp_vars, change_to_t0  # noqa: E402

machine_on()
home_all()
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
say("start", status(), "|", interp_vars())
c.mdi("T10")
wait_pin("prepare", True)
say("T10 preparing", status(), "prep", io("tool-prep-number"), io("tool-prep-pocket"))
say("T10 answered", answer("prepare", "prepared"), status(), "|", interp_vars())
c.mdi("M6")
wait_pin("change", True)
say("M6 changing at", pos(), status())
say("M6 answered", answer("change", "changed"), c.wait_complete(), status(),
    "pins", io("tool-number"), io("tool-from-pocket"), io("tool-prep-number"), "|", interp_vars())
c.mdi("G0 X1 Y1 Z1")
c.wait_complete()
c.mdi("T10")
say("T10 again answered", answer("prepare", "prepared"), status())
c.mdi("M6")
say("M6 of the loaded tool: change asked", wait_pin("change", True, 1.0), c.wait_complete(),
    "at", pos(), status())
say("M61 Q1", c.mdi("M61 Q1") or c.wait_complete(), status(), "pins", io("tool-number"), io("tool-from-pocket"))
change_to_t0()
say("errors", errors())
