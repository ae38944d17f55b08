/* cubic.c: Hermite interpolation of trajectory points to servo samples (traj_period > servo period). */
#include "cubic.h"

/* Start at rest at pos. */
void cubic_init(cubic_t *c, int rate, double pos)
{
    c->rate = rate > 0 ? rate : 1;
    c->step = c->rate;
    for (int i = 0; i < 4; i++)
        c->p[i] = pos;
    c->a = c->b = c->c = 0.0;
    c->d = pos;
}

/* A new point is due when the interval is used up. */
int cubic_needs_point(const cubic_t *c)
{
    return c->step >= c->rate;
}

/* Shift in the newest point and fit the p[1]..p[2] interval (Catmull-Rom tangents). */
void cubic_add_point(cubic_t *c, double pos)
{
    double m1, m2;

    c->p[0] = c->p[1];
    c->p[1] = c->p[2];
    c->p[2] = c->p[3];
    c->p[3] = pos;
    m1 = 0.5 * (c->p[2] - c->p[0]);
    m2 = 0.5 * (c->p[3] - c->p[1]);
    c->d = c->p[1];
    c->c = m1;
    c->b = 3.0 * (c->p[2] - c->p[1]) - 2.0 * m1 - m2;
    c->a = 2.0 * (c->p[1] - c->p[2]) + m1 + m2;
    c->step = 0;
}

/* At rest: the interval is used up and every point is the same. */
int cubic_settled(const cubic_t *c)
{
    return c->step >= c->rate && c->p[0] == c->p[3] && c->p[1] == c->p[3] && c->p[2] == c->p[3];
}

/* Evaluate the polynomial at the next sample of the interval. */
double cubic_sample(cubic_t *c, double servo_period, double *vel, double *acc)
{
    double t, interval = c->rate * servo_period;

    if (c->step < c->rate)
        c->step++;
    t = (double)c->step / c->rate;
    if (vel)
        *vel = (3.0 * c->a * t * t + 2.0 * c->b * t + c->c) / interval;
    if (acc)
        *acc = (6.0 * c->a * t + 2.0 * c->b) / (interval * interval);
    return ((c->a * t + c->b) * t + c->c) * t + c->d;
}
