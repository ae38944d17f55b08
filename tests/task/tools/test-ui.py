#!/usr/bin/env python3
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import hal  # noqa: E402
from taskui import c, s, say, errors, machine_on, home_all, mdi, linuxcnc  # noqa: E402


def tools():
    s.poll()
    return [(t.id, round(t.zoffset, 4)) for t in s.tool_table if t.id != -1 or t is s.tool_table[0]][:6]


machine_on()
home_all()
say("T4", mdi("T4"), "prep pins", hal.get_value("iocontrol.0.tool-prep-number"),
    hal.get_value("iocontrol.0.tool-prep-pocket"), hal.get_value("iocontrol.0.tool-prep-index"))
s.poll()
say("pocket_prepped", s.pocket_prepped)
say("M6", mdi("M6"), "tool_in_spindle", s.poll() or s.tool_in_spindle,
    "tool-number", hal.get_value("iocontrol.0.tool-number"), "from", hal.get_value("iocontrol.0.tool-from-pocket"),
    "prep-number", hal.get_value("iocontrol.0.tool-prep-number"))
say("G43", mdi("G43"), "tool_offset z", round(s.poll() or s.tool_offset[2], 4))
say("G10 L1 P4 Z0.5", mdi("G10 L1 P4 Z0.5"))
say("M61 Q99999", mdi("M61 Q99999"), "tool_in_spindle", s.poll() or s.tool_in_spindle)
say("G10 L1 P99999 Z2.5", mdi("G10 L1 P99999 Z2.5"))
say("T1 M6", mdi("T1 M6"), "tool_in_spindle", s.poll() or s.tool_in_spindle)
say("G10 L1 P1 Z0.7", mdi("G10 L1 P1 Z0.7"))
c.tool_offset(98876, 0.25, 0, 0, 0, 0, 0)
say("tool_offset()", c.wait_complete())
say("M61 Q0", mdi("M61 Q0"), "tool_in_spindle", s.poll() or s.tool_in_spindle)
say("T0 M6", mdi("T0 M6"), "tool_in_spindle", s.poll() or s.tool_in_spindle)
say("T7 (not in table)", mdi("T7"), errors())
say("table", tools())
c.load_tool_table()
c.wait_complete()
say("reloaded", tools())
