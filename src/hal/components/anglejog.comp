component anglejog "Jog two axes (or joints) together along a direction set by an angle, from one handwheel";
pin in bit enable_in "Jogging along the angle is allowed";
pin in s32 counts_in "Handwheel counts";
pin in float angle_degrees_in "Direction of the jog in degrees from the first (cos) axis toward the second (sin) axis";
pin in float scale_in "Distance along the line per handwheel count";
pin in s32 iscale_factor = 10000 "Integer factor by which the output counts are finer than counts-in (10..100000)";
pin in float accel_fraction_in = 1 "Fraction of the axis accelerations used for angle jogs";
pin in float max_vel "Largest speed along the line";
pin in float max_accel "Largest acceleration along the line";
pin out bit enable_out "enable-in (connect to both axes' jog-enable)";
pin out bit active "TRUE while the position along the line is moving";
pin out s32 coscounts "Counts for the first axis (connect axis.L.jog-counts)";
pin out s32 sincounts "Counts for the second axis (connect axis.L.jog-counts)";
pin out float cos_accel_fraction "accel-fraction-in * cos(angle) (connect axis.L.jog-accel-fraction)";
pin out float sin_accel_fraction "accel-fraction-in * sin(angle) (connect axis.L.jog-accel-fraction)";
pin out float current_angle_degrees "Angle in use (taken over only while disabled)";
pin out float current_scale "scale-in in use (taken over only while disabled)";
pin out float current_scale_out "current-scale / iscale-factor (connect both axes' jog-scale)";
pin out float current_vel "Speed along the line";
pin out float current_mag "Position along the line";
variable int started;
variable int ifactor;
variable int tot;
variable int prev_enable;
variable int prev_counts;
variable int waiting;
variable int bogus_told;
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """
LinuxCNC's anglejog, with its state kept per instance (LinuxCNC shares it between
instances, so only one of them works there). The handwheel counts, multiplied by
iscale-factor, command a position along the line (current-mag) that a simple
planner follows with max-vel and max-accel; coscounts and sincounts are that
position times cos and sin of the angle, in units of current-scale-out, for the
two axes' jog-counts in position mode.

The angle, the scale and iscale-factor are taken over only while enable-in is
FALSE; iscale-factor must be 10..100000 (a bogus value is reported once and the
old one kept). After enable-in rises nothing moves until the counts change.
A zero scale-in gives zero (or saturated) counts where LinuxCNC divides by zero.
""";
;;
#define AJ_IFACTOR_MIN 10
#define AJ_IFACTOR_MAX 100000

/* A double truncated toward zero into the s32 range; NaN gives 0. */
static int aj_s32(double v)
{
    if (v != v) return 0;
    if (v >= 2147483647.0) return 2147483647;
    if (v <= -2147483648.0) return -2147483647 - 1;
    return (int)v;
}

/* Take over the angle, the scale and (when it is sane) iscale-factor while disabled. */
static void aj_take_settings(struct __comp_state *__comp_inst)
{
    if (iscale_factor != ifactor) {
        if (iscale_factor >= AJ_IFACTOR_MIN && iscale_factor <= AJ_IFACTOR_MAX) {
            ifactor = iscale_factor;
            bogus_told = 0;
            rtapi_print("new ifactor=%d\n", ifactor);
        } else if (!bogus_told) {
            bogus_told = 1;
            rtapi_print("BOGUS iscale_factor=%d (min=%d max=%d)\n", ifactor, AJ_IFACTOR_MIN, AJ_IFACTOR_MAX);
        }
    }
    current_angle_degrees = angle_degrees_in;
    current_scale = scale_in;
    current_scale_out = scale_in / ifactor;
    tot = aj_s32(current_mag / current_scale_out);
}

/* Speed wanted to reach cmd without overshoot, 0 within a tiny band. */
static double aj_vreq(struct __comp_state *__comp_inst, double cmd, double dv, double tiny)
{
    double e = cmd - current_mag;
    if (e > tiny) {
        active = 1;
        return -dv + sqrt(2.0 * max_accel * e + dv * dv);
    }
    if (e < -tiny) {
        active = 1;
        return dv - sqrt(-2.0 * max_accel * e + dv * dv);
    }
    return 0.0;
}

/* Follow vreq within max-vel and max-accel, then publish the two axes' counts. */
static void aj_move(struct __comp_state *__comp_inst, double vreq, double dv, double t)
{
    double th = current_angle_degrees * M_PI / 180.0;
    if (vreq > max_vel) vreq = max_vel;
    if (vreq < -max_vel) vreq = -max_vel;
    if (vreq > current_vel + dv) current_vel += dv;
    else if (vreq < current_vel - dv) current_vel -= dv;
    else current_vel = vreq;
    if (current_vel != 0.0) active = 1;
    current_mag += current_vel * t;
    coscounts = aj_s32(current_mag * cos(th) / current_scale_out);
    sincounts = aj_s32(current_mag * sin(th) / current_scale_out);
    cos_accel_fraction = accel_fraction_in * cos(th);
    sin_accel_fraction = accel_fraction_in * sin(th);
}

FUNCTION(_)
{
    double t = fperiod, dv = max_accel * t, tiny = max_accel * t * t * 0.001, vreq = 0.0;
    if (!started) {
        started = 1;
        current_angle_degrees = angle_degrees_in;
        current_scale = scale_in;
        ifactor = iscale_factor;
        current_scale_out = scale_in / ifactor;
    }
    int nc = (int)((unsigned int)ifactor * (unsigned int)counts_in);
    if (enable_in && !prev_enable) {
        prev_counts = nc;
        waiting = 1;
        tot = aj_s32(current_mag / current_scale_out);
    }
    int delta = (int)((unsigned int)nc - (unsigned int)prev_counts);
    prev_enable = enable_in;
    prev_counts = nc;
    enable_out = enable_in;
    if (delta != 0) waiting = 0;
    if (enable_in) tot = (int)((unsigned int)tot + (unsigned int)delta);
    double cmd = tot * current_scale_out;
    active = 0;
    if (enable_in && !waiting) {
        vreq = aj_vreq(__comp_inst, cmd, dv, tiny);
    } else {
        if (!enable_in) aj_take_settings(__comp_inst);
        if (waiting) return;
    }
    aj_move(__comp_inst, vreq, dv, t);
}
