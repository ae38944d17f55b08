/* simple_tp.c: one-dimensional trapezoid planner (free-mode joints, teleop axes, external offsets). */
#include <math.h>
#include "simple_tp.h"

/* Place the planner at rest at pos. */
void simple_tp_reset(simple_tp_t *tp, double pos)
{
    tp->pos_cmd = pos;
    tp->curr_pos = pos;
    tp->curr_vel = 0.0;
    tp->curr_acc = 0.0;
    tp->active = 0;
}

/* Distance needed to stop from the current velocity at max_acc. */
double simple_tp_stop_distance(const simple_tp_t *tp)
{
    if (tp->max_acc <= 0.0)
        return 0.0;
    return tp->curr_vel * tp->curr_vel / (2.0 * tp->max_acc);
}

/* Largest speed that still stops exactly at distance d (signed) in steps of
 * pos += v * period with the speed falling by at most dv = acc * period per step:
 * braking from v covers S(v) = period * sum_{k=0..n} (v - k dv), n = floor(v / dv);
 * this inverts S, so a move decelerates by exactly dv per step and lands on the target. */
static double braking_velocity(double d, double acc, double period)
{
    double dv = acc * period, dist = fabs(d), unit = period * dv, v, n;

    if (dist <= 0.0)
        return 0.0;
    n = floor((-1.0 + sqrt(1.0 + 8.0 * dist / unit)) / 2.0);
    v = (dist / period + dv * n * (n + 1.0) / 2.0) / (n + 1.0);
    return d < 0.0 ? -v : v;
}

/* Clamp v to [lo, hi]. */
static double clamp(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* One period of motion toward pos_cmd (or to a stop when disabled); pos += v * period. */
void simple_tp_update(simple_tp_t *tp, double period)
{
    double max_vel = tp->max_vel > 0.0 ? tp->max_vel : 0.0;
    double max_acc = tp->max_acc;
    double dv, d = 0.0, vel, vel_old = tp->curr_vel;

    if (period <= 0.0 || !(max_acc > 0.0)) {
        tp->curr_acc = 0.0;
        return;
    }
    dv = max_acc * period;
    if (tp->enable) {
        d = tp->pos_cmd - tp->curr_pos;
        vel = braking_velocity(d, max_acc, period);
    } else {
        vel = 0.0;
    }
    vel = clamp(vel, -max_vel, max_vel);
    vel = clamp(vel, vel_old - dv, vel_old + dv);
    tp->curr_pos += vel * period;
    if (tp->enable && fabs(tp->pos_cmd - tp->curr_pos) <= 1e-12 * fmax(1.0, fabs(tp->pos_cmd)))
        tp->curr_pos = tp->pos_cmd;     /* rounding of the last step */
    tp->curr_vel = vel;
    tp->curr_acc = (vel - vel_old) / period;
    if (tp->enable)
        tp->active = vel != 0.0 || tp->curr_pos != tp->pos_cmd;
    else
        tp->active = vel != 0.0;
    if (!tp->active && !tp->enable)
        tp->pos_cmd = tp->curr_pos;
}
