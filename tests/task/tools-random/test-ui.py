#!/usr/bin/env python3
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import hal  # noqa: E402
from taskui import s, say, errors, machine_on, home_all, mdi  # noqa: E402


def pockets():
    s.poll()
    return [(i, t.id) for i, t in enumerate(s.tool_table[:5])]


s.poll()
say("start tool_in_spindle", s.tool_in_spindle, pockets())
machine_on()
home_all()
say("T2", mdi("T2"), "prep pocket", hal.get_value("iocontrol.0.tool-prep-pocket"))
say("M6", mdi("M6"), "tool_in_spindle", s.poll() or s.tool_in_spindle, "from", hal.get_value("iocontrol.0.tool-from-pocket"))
say("after swap", pockets())
say("G10 L1 P5 Z0.55", mdi("G10 L1 P5 Z0.55"))
say("T3 M6", mdi("T3 M6"), pockets())
say("errors", errors())
