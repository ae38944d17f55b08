component eoffset_per_angle "External offset computed from an angle (polygons and waves)";
pin in bit active "From motion.eoffset-active: an external offset is applied";
pin in bit is_on "From halui.machine.is-on";
pin in bit enable_in "Compute offsets (connect a user switch)";
pin in float radius_ref = 1 "Reference radius: the circle the offsets are built on";
pin in float angle "Input angle in degrees (rotary coordinate or spindle position)";
pin in float start_angle "Angle in degrees of the first polygon corner or wave start";
pin in s32 fnum "Function: 0 inside polygon, 1 outside polygon, 2 sinusoid, 3 square wave (others: 0)";
pin in float rfraction = 0.1 "Wave amplitude as a fraction of radius-ref";
pin in float fmult = 6 "Wave periods per revolution, or the polygon's number of sides (3 or more)";
pin in u32 k = 10000 "Counts per unit of offset on kcounts (0 means 10000)";
pin out bit is_off "NOT is-on (for convenience)";
pin out bit enable_out "To axis.L.eoffset-enable";
pin out bit clear "To axis.L.eoffset-clear: TRUE while the machine is off";
pin out s32 kcounts "To axis.L.eoffset-counts: the offset times k";
pin out float kreciprocal "To axis.L.eoffset-scale: 1/k";
pin out float eoffset_dbg "Offset computed this period, in machine units (debug)";
pin out u32 state_dbg "State (debug): 0 off, 1 ready, 2 running, 3 stopping, 4 stopped by bad settings";
variable int state;
function _ "Compute the offset";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """
Computes an external offset from an angle, for shaping a part while a rotary
coordinate or the spindle turns: kcounts goes to axis.L.eoffset-counts and
kreciprocal (1/k) to axis.L.eoffset-scale.

fnum selects the function, with u = angle - start-angle:

0: inside polygon. A regular polygon with fmult corners on the circle of radius
radius-ref, the first corner at start-angle; the offset (zero or negative) is the
distance from the circle in to the polygon along the radius at the angle.

1: outside polygon. A regular polygon of fmult sides touching the circle of radius
radius-ref, the first corner at start-angle; the offset (zero or positive) is the
distance from the circle out to the polygon.

2: sinusoid: rfraction * radius-ref * sin(fmult * u).

3: square wave: plus rfraction * radius-ref where that sinusoid is zero or positive,
minus it elsewhere.

Other fnum values use function 0. The polygons need a whole fmult of 3 or more.

States (state-dbg): with the machine off (0) clear is TRUE, enable-out FALSE and
kcounts 0. With the machine on and enable-in FALSE the component is ready (1).
enable-in TRUE starts it (2): enable-out TRUE and kcounts follows the function.
When enable-in drops, kcounts goes to 0 while enable-out stays TRUE (3), so motion
removes the offset within its own limits; once motion reports active FALSE,
enable-out drops and the component is ready again. Settings a function cannot use
(a polygon with fewer than 3 or a fractional number of sides, a NaN result) stop
it the same way (4); enable-in must then be toggled to start again.
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

/* Offset of function fn at u degrees past start-angle into *off; -1 when the settings do not fit it. */
static int offset_at(struct __comp_state *__comp_inst, int fn, double u, double *off)
{
    double r = radius_ref, amp = rfraction * radius_ref, n = fmult;
    if (fn < 0 || fn > 3)
        fn = 0;
    if (fn <= 1 && !(n >= 3 && n == floor(n) && n < 1e6))
        return -1;
    if (fn == 0)
        *off = r * polygon_radius(u, (int)n) - r;
    else if (fn == 1)
        *off = r * polygon_radius(u, (int)n) / cos(M_PI / n) - r;
    else if (fn == 2)
        *off = amp * sin(fmult * u * M_PI / 180.0);
    else
        *off = sin(fmult * u * M_PI / 180.0) >= 0 ? amp : -amp;
    return *off == *off ? 0 : -1;
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

enum { EPA_OFF, EPA_READY, EPA_RUNNING, EPA_STOPPING, EPA_BAD };

/* The state after this period's inputs (machine, switch, motion's active flag). */
static int next_state(struct __comp_state *__comp_inst, int st)
{
    if (!is_on)
        return EPA_OFF;
    switch (st) {
    case EPA_OFF:
    case EPA_READY:
        return enable_in ? EPA_RUNNING : EPA_READY;
    case EPA_RUNNING:
        return enable_in ? EPA_RUNNING : EPA_STOPPING;
    case EPA_STOPPING:
        return active ? EPA_STOPPING : EPA_READY;
    default:
        return (!active && !enable_in) ? EPA_READY : EPA_BAD;
    }
}

/* Compute this period's offset and the external-offset control outputs. */
FUNCTION(_)
{
    double off = 0.0, kk = k ? (double)k : 10000.0;
    state = next_state(__comp_inst, state);
    if (state == EPA_RUNNING && offset_at(__comp_inst, fnum, angle - start_angle, &off) < 0) {
        off = 0.0;
        state = EPA_BAD;
    }
    is_off = !is_on;
    clear = !is_on;
    enable_out = state == EPA_RUNNING || state == EPA_STOPPING || (state == EPA_BAD && active);
    kreciprocal = 1.0 / kk;
    eoffset_dbg = off;
    kcounts = offset_counts(off * kk);
    state_dbg = state;
}
