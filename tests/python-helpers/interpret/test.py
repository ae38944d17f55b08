#!/usr/bin/env python3
"""preview_helpers and rs274.interpret against a stand-in stat object and a stand-in gcode module
(only arc_to_segments is used, recorded rather than computed)."""
import sys
import types
from collections import namedtuple

fake_gcode = types.ModuleType("gcode")
fake_gcode.calls = []
fake_gcode.arc_to_segments = lambda canon, *args: fake_gcode.calls.append(args) or [("seg",)]
sys.modules["gcode"] = fake_gcode

import preview_helpers  # noqa: E402
import rs274  # noqa: E402
from rs274 import interpret  # noqa: E402

Tool = namedtuple("Tool", "id xoffset yoffset zoffset")


class Stat:
    """Just the attributes the helpers read."""
    linear_units = 1.0
    angular_units = 0.0
    axis_mask = 0b101001          # X, A, C
    block_delete = True
    position = (1.5, 0, 0, 370.25, 0, -30.0, 0, 0, 0)
    gcodes = [-1] * 17
    tool_table = [Tool(-1, 0, 0, 0), Tool(5, 0, 0, 1.5), Tool(7, 0, 0, 2.5)]

    def poll(self):
        """Nothing to refresh."""


class Ini:
    """getbool for WRAPPED_ROTARY: only A wraps."""
    def getbool(self, section, key, fallback=None):
        return section == "AXIS_A"


s = Stat()
s.gcodes[3], s.gcodes[6], s.gcodes[14] = 170, 200, 911
print(preview_helpers.create_unitcode_and_initcode(s, Ini()))
s.linear_units = 0.03937
print(preview_helpers.create_unitcode_and_initcode(s, Ini())[0])


class Canon(interpret.Translated, interpret.ArcsToSegmentsMixin, interpret.PrintCanon):
    """Prints what Translated hands on."""
    def straight_traverse_translated(self, *pos):
        print("traverse", " ".join("%g" % p for p in pos))

    def straight_arcsegments(self, segs):
        print("arc segments", segs)


c = Canon()
c.set_g92_offset(1, 0, 0, 0, 0, 0, 0, 0, 0)
c.set_xy_rotation(90)
c.set_g5x_offset(2, 10, 20, 0, 0, 0, 0, 0, 0, 0)
c.straight_traverse(1, 0, 5, 0, 0, 0, 0, 0, 0)
print("g5x index", c.g5x_index, "rotation sin %.3f" % c.rotation_sin)
c.set_plane(3)
c.arc_feed(1, 2, 0, 0, 1, 3, 0, 0, 0, 0, 0, 0)
print("gcode.arc_to_segments got", fake_gcode.calls[-1])
pc = interpret.PrintCanon()
pc.straight_feed(1, 2, 3, 4, 5, 6)
pc.arc_feed(1, 2, 3, 4, 5, 6, 7, 8, 9)
pc.dwell(0.05)
pc.dwell(2)
pc.comment("hello")

m = interpret.StatMixin(s, False)
m.change_tool(7)
print("non-random T7 ->", m.get_tool(0), "index of 5:", m.get_index(5), "missing:", m.get_index(9))
m.change_tool(9)
print("non-random unknown tool ->", m.get_tool(0))
r = interpret.StatMixin(s, True)
r.change_tool(7)
print("random T7: spindle", r.tools[0].id, "global", interpret.tool_in_spindle,
      "get_tool(2)", r.get_tool(2), "out of range", r.get_tool(9))
print("units", r.get_external_angular_units(), r.get_external_length_units(),
      "mask", r.get_axis_mask(), "block delete", r.get_block_delete())
print("package exports", rs274.Translated is interpret.Translated)
