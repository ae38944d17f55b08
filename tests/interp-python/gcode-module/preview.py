#!/usr/bin/env python3
"""Drive gcode.parse with a recording canon and print what a preview receives."""
import os
import tempfile

import gcode


class Recorder:
    """The canon a preview implements: every call printed with rounded numbers."""

    def __init__(self, abort_after=None):
        self.var = tempfile.NamedTemporaryFile(suffix=".var")
        self.parameter_file = self.var.name
        self.lo = (0.0,) * 9
        self.plane = 1
        self.calls = 0
        self.abort_after = abort_after

    def _show(self, name, *args):
        self.calls += 1
        if self.abort_after is not None:
            return
        text = " ".join("%g" % round(a, 4) if isinstance(a, float) else str(a) for a in args)
        print("%s %s" % (name, text))

    def next_line(self, code):
        if self.abort_after is None:
            print("-- line %d motion %d" % (code.sequence_number, code.gcodes[1]))

    def straight_traverse(self, *p):
        self._show("traverse", *p[:3])
        self.lo = p

    def straight_feed(self, *p):
        self._show("feed", *p[:3])
        self.lo = p

    def arc_feed(self, *a):
        self._show("arc", *a[:6])
        segs = gcode.arc_to_segments(self, *a, 8)
        print("   %d segments, last %s" % (len(segs), tuple(round(v, 4) for v in segs[-1][:3])))
        self.lo = segs[-1]

    def set_plane(self, p):
        self.plane = p
        self._show("plane", p)

    def comment(self, t): self._show("comment", t)
    def message(self, t): self._show("message", t)
    def set_feed_rate(self, f): self._show("feed rate", f)
    def dwell(self, t): self._show("dwell", t)
    def change_tool(self, pocket): self._show("change tool", pocket)
    def tool_offset(self, *p): self._show("tool offset", *p[:3])
    def set_g5x_offset(self, *a): self._show("g5x", *a[:4])
    def set_g92_offset(self, *a): self._show("g92", *a[:3])
    def set_xy_rotation(self, r): self._show("rotation", r)
    def get_external_length_units(self): return 1.0
    def get_external_angular_units(self): return 1.0
    def get_axis_mask(self): return 7
    def get_block_delete(self): return False

    def get_tool(self, index):
        tools = [(-1,) + (0.0,) * 12 + (0,), (4, 0.0, 0.0, 2.5) + (0.0,) * 9 + (0,)]
        return tools[index] if index < len(tools) else tools[0]

    def check_abort(self):
        return self.abort_after is not None and self.calls >= self.abort_after


class Broken(Recorder):
    def comment(self, t):
        raise ValueError("the canon refused comment %r" % t)


def run(program, canon, initcode=""):
    result, seq = gcode.parse(program, canon, "G21", initcode)
    state = "error: " + gcode.strerror(result) if result > gcode.MIN_ERROR else "result %d" % result
    print("== %s: %s, last line %d" % (program, state, seq))


run("shapes.ngc", Recorder(), "G17 G40")
run("bad-arc.ngc", Recorder())
quiet = Recorder(abort_after=5)
run("loop.ngc", quiet)
print("   (%d canon calls before it stopped)" % quiet.calls)
os.environ["INI_FILE_NAME"] = "remap.ini"
run("remapped.ngc", Recorder())
del os.environ["INI_FILE_NAME"]
try:
    run("shapes.ngc", Broken())
except ValueError as e:
    print("== the canon's exception came through:", e)
