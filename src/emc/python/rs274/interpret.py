"""rs274.interpret: canon mix-ins for gcode.parse(): offsets and XY rotation, arcs as segments,
a printing canon and the tool/status answers a preview needs from a linuxcnc.stat()."""
import math

AXES = "xyzabcuvw"

# the tool in the spindle as StatMixin.change_tool leaves it on a random changer (-1 = none)
tool_in_spindle = -1
# the tool entry of an empty spindle: id -1, twelve zero offsets/geometry values, orientation 0
empty_spindle_data = (-1,) + (0.0,) * 12 + (0,)


class Translated:
    """Applies G92, rotation and G5x offsets to traverse and feed moves, then calls the
    *_translated methods the subclass provides."""
    g92_offset_x = g92_offset_y = g92_offset_z = g92_offset_a = g92_offset_b = 0
    g92_offset_c = g92_offset_u = g92_offset_v = g92_offset_w = 0
    g5x_offset_x = g5x_offset_y = g5x_offset_z = g5x_offset_a = g5x_offset_b = 0
    g5x_offset_c = g5x_offset_u = g5x_offset_v = g5x_offset_w = 0
    rotation_xy = 0

    def rotate_and_translate(self, x, y, z, a, b, c, u, v, w):
        """Program coordinates to machine coordinates: G92, then the XY rotation, then G5x."""
        pos = [x, y, z, a, b, c, u, v, w]
        pos = [p + getattr(self, "g92_offset_" + n) for p, n in zip(pos, AXES)]
        if self.rotation_xy:
            t = math.radians(self.rotation_xy)
            cos_t, sin_t = math.cos(t), math.sin(t)
            pos[0], pos[1] = pos[0] * cos_t - pos[1] * sin_t, pos[0] * sin_t + pos[1] * cos_t
        return tuple(p + getattr(self, "g5x_offset_" + n) for p, n in zip(pos, AXES))

    def straight_traverse(self, *args):
        """A rapid move, translated."""
        return self.straight_traverse_translated(*self.rotate_and_translate(*args))

    def straight_feed(self, *args):
        """A feed move, translated."""
        return self.straight_feed_translated(*self.rotate_and_translate(*args))

    def set_g5x_offset(self, index, x, y, z, a, b, c, u=None, v=None, w=None):
        """Remember the active G5x system and its offsets."""
        self.g5x_index = index
        for name, value in zip(AXES, (x, y, z, a, b, c, u, v, w)):
            setattr(self, "g5x_offset_" + name, value)

    def set_g92_offset(self, x, y, z, a, b, c, u=None, v=None, w=None):
        """Remember the G92 offsets."""
        for name, value in zip(AXES, (x, y, z, a, b, c, u, v, w)):
            setattr(self, "g92_offset_" + name, value)

    def set_xy_rotation(self, theta):
        """Remember the XY rotation (degrees) with its sine and cosine."""
        self.rotation_xy = theta
        t = math.radians(theta)
        self.rotation_cos = math.cos(t)
        self.rotation_sin = math.sin(t)


class ArcsToSegmentsMixin:
    """Turns arc_feed into straight segments (gcode.arc_to_segments) in the active plane."""
    plane = 1
    arcdivision = 64

    def set_plane(self, plane):
        """Remember the plane (1 XY, 2 YZ, 3 XZ, ...)."""
        self.plane = plane

    def arc_feed(self, x1, y1, cx, cy, rot, z1, a, b, c, u, v, w):
        """Cut the arc into segments and hand them to straight_arcsegments."""
        import gcode
        segs = gcode.arc_to_segments(self, x1, y1, cx, cy, rot, z1, a, b, c, u, v, w,
                                     self.arcdivision)
        self.straight_arcsegments(segs)


class PrintCanon:
    """A canon that prints every call it gets, one line each."""

    def set_g5x_offset(self, *args):
        """Print the G5x offset call."""
        print("set_g5x_offset", args)

    def set_g92_offset(self, *args):
        """Print the G92 offset call."""
        print("set_g92_offset", args)

    def next_line(self, state):
        """Print the line number of the next block and keep its state."""
        print("next_line", state.sequence_number)
        self.state = state

    def set_plane(self, plane):
        """Print the plane selection."""
        print("set plane", plane)

    def set_feed_rate(self, arg):
        """Print the feed rate."""
        print("set feed rate", arg)

    def comment(self, arg):
        """Print a comment."""
        print("#", arg)

    def straight_traverse(self, *args):
        """Print a rapid move (X Y Z and A B C)."""
        print("straight_traverse %.4g %.4g %.4g  %.4g %.4g %.4g" % args)

    def straight_feed(self, *args):
        """Print a feed move (X Y Z and A B C)."""
        print("straight_feed %.4g %.4g %.4g  %.4g %.4g %.4g" % args)

    def dwell(self, arg):
        """Print a dwell, in ms below 0.1 s."""
        if arg < .1:
            print("dwell %f ms" % (1000 * arg))
        else:
            print("dwell %f seconds" % arg)

    def arc_feed(self, *args):
        """Print an arc move."""
        print("arc_feed %.4g %.4g  %.4g %.4g %.4g  %.4g  %.4g %.4g %.4g" % args)


class StatMixin:
    """Answers the interpreter's questions about tools, units and axes from a linuxcnc.stat();
    tool changes are simulated on a copy of the tool table."""

    def __init__(self, s, r):
        """s: a polled linuxcnc.stat(); r: True for a random tool changer."""
        self.s = s
        self.tools = list(s.tool_table)
        self.random = r

    def change_tool(self, pocket):
        """Put tool `pocket` (a tool number) in the spindle entry of the copied table."""
        global tool_in_spindle
        idx = self.get_index(pocket)
        if self.random:
            self.tools[0], self.tools[idx] = self.tools[idx], self.tools[0]
            tool_in_spindle = idx
        elif idx == 0:
            self.tools[0] = empty_spindle_data
        else:
            self.tools[0] = self.tools[idx]

    def get_index(self, n):
        """1-based position of tool n in the table after the spindle entry, 0 if absent."""
        for idx, tool in enumerate(self.tools[1:], 1):
            if tool.id == n:
                return idx
        return 0

    def get_tool(self, idx):
        """The table entry at idx (the spindle's for the random changer's tool), as a tuple."""
        if 0 <= idx < len(self.tools):
            if idx == tool_in_spindle:
                return tuple(self.tools[0])
            return tuple(self.tools[idx])
        return empty_spindle_data

    def get_external_angular_units(self):
        """Angular units of the machine (1.0 when the status has none)."""
        return self.s.angular_units or 1.0

    def get_external_length_units(self):
        """Linear units of the machine (1.0 when the status has none)."""
        return self.s.linear_units or 1.0

    def get_axis_mask(self):
        """The machine's axis mask."""
        return self.s.axis_mask

    def get_block_delete(self):
        """Whether block delete is on."""
        return self.s.block_delete
