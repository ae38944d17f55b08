/* hm2_stepgen_motion.c: the stepgen's velocity planning per cycle (LinuxCNC's matching rule). */
#include <math.h>
#include <stdint.h>
#include "hm2_stepgen_motion.h"

/* Clamp v to centre +- span (span >= 0). */
static double clamp_around(double v, double centre, double span)
{
    if (v > centre + span)
        return centre + span;
    if (v < centre - span)
        return centre - span;
    return v;
}

/* Position mode: accelerate towards the commanded velocity so that, when the velocities
   match, the position matches too; near the match, close the position error directly. */
double hm2_stepgen_position_velocity(double position_cmd, double old_position_cmd,
                                     double position_fb, double velocity_fb,
                                     double maxaccel, double period_s,
                                     hm2_stepgen_debug_t *dbg)
{
    double ff = (position_cmd - old_position_cmd) / period_s;
    double e_v = velocity_fb - ff;
    double a = 0.0;
    if (e_v > 0)
        a = maxaccel > 0 ? -maxaccel : -e_v / period_s;
    else if (e_v < 0)
        a = maxaccel > 0 ? maxaccel : e_v / period_s;
    double t = a == 0.0 ? 0.0 : -e_v / a;
    double p_match = position_fb + ((ff + velocity_fb) / 2.0) * (t + period_s);
    double c_match = position_cmd + ff * t;
    double err = p_match - c_match;
    double v;
    if (t < period_s) {
        v = ff - 0.5 * err / period_s;
        if (maxaccel > 0)
            v = clamp_around(v, velocity_fb, maxaccel * period_s);
    } else {
        double dp = (-2.0 * a * period_s) * t;
        if (fabs(err + 2.0 * dp) < fabs(err))
            a = -a;
        v = velocity_fb + a * period_s;
    }
    if (dbg) {
        dbg->ff_vel = ff;
        dbg->vel_error = e_v;
        dbg->s_to_match = t;
        dbg->err_at_match = err;
    }
    return v;
}

/* Velocity mode: follow velocity_cmd, at most maxaccel * period away from the last value. */
double hm2_stepgen_velocity_velocity(double velocity_cmd, double velocity_fb,
                                     double maxaccel, double period_s)
{
    if (maxaccel > 0)
        return clamp_around(velocity_cmd, velocity_fb, maxaccel * period_s);
    return velocity_cmd;
}

/* Signed DDS increment per clock, as the register holds it. */
unsigned hm2_stepgen_rate_register(double velocity, double position_scale, double clock_hz)
{
    double steps_per_s = velocity * position_scale;
    double rate = steps_per_s * 4294967296.0 / clock_hz;
    if (rate > 2147483647.0)
        rate = 2147483647.0;
    if (rate < -2147483648.0)
        rate = -2147483648.0;
    return (unsigned)(uint32_t)(int32_t)rate;
}
