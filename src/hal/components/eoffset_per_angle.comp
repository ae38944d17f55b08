component eoffset_per_angle "External offset computed from an angle (polygons and waves)";
pin in bit enable_in "Compute offsets (connect a user switch)";
pin in bit is_on "Machine is on (connect halui.machine.is-on)";
pin in float angle "Input angle in degrees (rotary coordinate or spindle position)";
pin in float start_angle "Angle in degrees of the first polygon corner or wave start";
pin in float radius_ref = 1 "Reference radius: the circle the polygons are built on";
pin in float rfraction = 0.1 "Wave amplitude as a fraction of radius-ref";
pin in float fmult = 6 "Wave periods per revolution";
pin in s32 fnum "Function: 0 inside polygon, 1 outside polygon, 2 sinusoid, 3 square wave";
pin in s32 edges = 6 "Polygon edge count (3 or more)";
pin in float k = 10000 "Counts per unit of offset on kcounts (set axis.L.eoffset-scale to 1/k)";
pin out s32 kcounts "Offset times k (connect axis.L.eoffset-counts)";
pin out bit kreset "TRUE while the machine is off (connect axis.L.eoffset-clear)";
pin out bit active "TRUE while offsets are computed, and one period after (connect axis.L.eoffset-enable)";
pin out float eoffset_dbg "Offset computed this period, in machine units";
variable int was_on;
function _ "Compute the offset";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """
Computes an external offset from an angle, for shaping a part while a rotary
coordinate or the spindle turns: the result goes to axis.L.eoffset-counts as counts,
scaled by k.

fnum selects the function, with u = angle - start-angle:

0: inside polygon. A regular polygon with edges corners on the circle of radius
radius-ref, the first corner at start-angle; the offset (zero or negative) is the
distance from the circle in to the polygon along the radius at the angle.

1: outside polygon. A regular polygon whose edges touch the circle of radius
radius-ref, the first corner at start-angle; the offset (zero or positive) is the
distance from the circle out to the polygon.

2: sinusoid: rfraction * radius-ref * sin(fmult * u).

3: square wave: plus rfraction * radius-ref where that sinusoid is zero or positive,
minus it elsewhere.

Other fnum values give a zero offset; edges below 3 count as 3.
Offsets are computed while enable-in and is-on are both TRUE. When enable-in drops,
kcounts becomes 0 and active stays TRUE for that one more period, so the axis takes
the zero target and removes the offset at its own limits; then active drops. kreset
is NOT is-on, to clear the offset at once when the machine goes off.
""";
;;
/* Radius factor of a polygon at u degrees past a corner: corners on the unit circle. */
static double polygon_radius(double u, int n)
{
    double pitch = 360.0 / n, w = fmod(u, pitch);
    if (w < 0)
        w += pitch;
    return cos(M_PI / n) / cos((w - pitch / 2) * M_PI / 180.0);
}

/* Offset of function fn at u degrees past start-angle. */
static double offset_at(struct __comp_state *__comp_inst, int fn, double u)
{
    int n = edges < 3 ? 3 : edges;
    double r = radius_ref, amp = rfraction * radius_ref, s;
    switch (fn) {
    case 0:
        return r * polygon_radius(u, n) - r;
    case 1:
        return r * polygon_radius(u, n) / cos(M_PI / n) - r;
    case 2:
        return amp * sin(fmult * u * M_PI / 180.0);
    case 3:
        s = sin(fmult * u * M_PI / 180.0);
        return s >= 0 ? amp : -amp;
    default:
        return 0.0;
    }
}

/* Counts for an offset, limited to the s32 range (NaN gives 0). */
static int offset_counts(double v)
{
    if (v != v)
        return 0;
    if (v > 2147483647.0)
        return 2147483647;
    if (v < -2147483648.0)
        return -2147483647 - 1;
    return (int)floor(v + 0.5);
}

/* Compute this period's offset and the external-offset control outputs. */
FUNCTION(_)
{
    double off = 0.0;
    int on = enable_in && is_on;
    active = on || (was_on && is_on);
    was_on = on;
    kreset = !is_on;
    if (on)
        off = offset_at(__comp_inst, fnum, angle - start_angle);
    eoffset_dbg = off;
    kcounts = offset_counts(off * k);
}
