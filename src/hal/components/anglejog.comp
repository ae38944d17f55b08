component anglejog "Jog two axes (or joints) along a line at an angle with one handwheel";
pin in bit enable_in "Jogging along the angle is allowed";
pin in bit is_on = TRUE "Machine is on (connect halui.machine.is-on); FALSE disables jogging";
pin in s32 counts_in "Handwheel counts";
pin in float jog_angle "Direction of the jog in degrees from the first (cos) axis toward the second (sin) axis";
pin in float scale_in = 0.001 "Distance along the line per handwheel count";
pin in float accel_fraction = 1 "Fraction (0..1) of the axis accelerations used for angle jogs";
pin in s32 iscale_factor = 1000 "Integer factor by which the output counts are finer than counts-in (at least 1)";
pin out bit active "TRUE while jogging is enabled (connect to both axes' jog-enable)";
pin out float current_angle "Angle in use; jog-angle is taken over only while not active";
pin out s32 cos_counts "Counts for the first axis (connect axis.L.jog-counts)";
pin out s32 sin_counts "Counts for the second axis (connect axis.L.jog-counts)";
pin out float coscale "Jog scale for the first axis (connect axis.L.jog-scale)";
pin out float sinscale "Jog scale for the second axis (connect axis.L.jog-scale)";
pin out float cos_accel_fraction "accel-fraction times |cos(angle)| (connect axis.L.jog-accel-fraction)";
pin out float sin_accel_fraction "accel-fraction times |sin(angle)| (connect axis.L.jog-accel-fraction)";
variable double cos_acc;
variable double sin_acc;
variable int old_counts;
variable int started;
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """
Turns one handwheel into a jog of two axes along a straight line at jog-angle degrees.
Each change of counts-in is split into the two axes: the first gets
change * iscale-factor * cos(angle) counts on cos-counts, the second
change * iscale-factor * sin(angle) counts on sin-counts, and both scales are
scale-in / iscale-factor, so the tool moves scale-in per handwheel count along the line.
Fractions of an output count are carried over, so no distance is lost to rounding.

The axis accelerations are shared out by the cos-accel-fraction and sin-accel-fraction
outputs so both axes start and stop together. Use the jog position mode of the axes.

active is enable-in AND is-on. While not active, handwheel counts are ignored and
current-angle follows jog-angle; once active, the angle stays fixed until active drops.
""";
;;
#define TWO_POW_31 2147483648.0
#define TWO_POW_32 4294967296.0

/* Keep an accumulator inside the s32 range, wrapping like the counter it feeds
   (a NaN or infinite value from a bad angle restarts it at 0). */
static double wrap_s32(double v)
{
    if (v != v || v - v != 0)
        return 0.0;
    if (v >= TWO_POW_31 || v < -TWO_POW_31)
        v -= TWO_POW_32 * floor((v + TWO_POW_31) / TWO_POW_32);
    return v;
}

/* Nearest s32 of a wrapped accumulator. */
static int round_s32(double v)
{
    double r = floor(v + 0.5);
    if (r >= TWO_POW_31)
        r -= TWO_POW_32;
    return (int)r;
}

/* Publish scales and acceleration fractions for the angle in use. */
static void update_scales(struct __comp_state *__comp_inst, int ifac)
{
    double rad = current_angle * M_PI / 180.0, af = accel_fraction;
    if (af < 0)
        af = 0;
    if (af > 1)
        af = 1;
    coscale = scale_in / ifac;
    sinscale = scale_in / ifac;
    cos_accel_fraction = af * fabs(cos(rad));
    sin_accel_fraction = af * fabs(sin(rad));
}

/* Split the handwheel change into the two axes while active. */
FUNCTION(_)
{
    int ifac = iscale_factor < 1 ? 1 : iscale_factor;
    int delta = (int)((unsigned)counts_in - (unsigned)old_counts);
    double rad;
    if (!started)
        delta = 0;
    started = 1;
    old_counts = counts_in;
    active = enable_in && is_on;
    if (!active) {
        current_angle = jog_angle;
        delta = 0;
    }
    rad = current_angle * M_PI / 180.0;
    cos_acc = wrap_s32(cos_acc + (double)delta * ifac * cos(rad));
    sin_acc = wrap_s32(sin_acc + (double)delta * ifac * sin(rad));
    cos_counts = round_s32(cos_acc);
    sin_counts = round_s32(sin_acc);
    update_scales(__comp_inst, ifac);
}
