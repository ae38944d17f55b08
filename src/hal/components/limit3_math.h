/* limit3_math.h: limit3's follower, one period at a time; pure math shared by the component and its unit test. */
#ifndef LIMIT3_MATH_H
#define LIMIT3_MATH_H

#include <math.h>

#define LIMIT3_EPS 1e-9

/* What the follower remembers between periods. */
typedef struct {
    double pos;         /* last output */
    double pos_prev;    /* output one period earlier */
    double target_prev; /* target of the previous period */
} limit3_state_t;

/* The constraints, as the pins give them. */
typedef struct {
    double pos_min, pos_max, vel_max, acc_max;
    unsigned smooth_periods; /* the smooth-steps pin */
} limit3_limits_t;

/* Where the output can be next period and what the goal of this period is. */
typedef struct {
    double v_out, v_in, p_lo, p_hi, v_lo, v_hi;
    double g_lo, g_hi, g_cur, g_prev, dv, a_lo, a_hi;
} limit3_plan_t;

/* Accept the new output value and shift the history. */
static inline void limit3_commit(limit3_state_t *st, double y, double x)
{
    st->pos_prev = st->pos;
    st->pos = y;
    st->target_prev = x;
}

/* Fix the goal on one limit: used when following would overshoot it. */
static inline void limit3_goal_limit(limit3_plan_t *p, double limit)
{
    p->g_lo = p->g_hi = p->g_cur = p->g_prev = limit;
}

/* Reachable window and goal: the input, or a position limit it would overshoot. */
static inline void limit3_plan(limit3_plan_t *p, const limit3_state_t *st,
                               const limit3_limits_t *lim, double x, double T)
{
    double y = st->pos;
    p->v_in = (x - st->target_prev) / T;
    p->v_out = (y - st->pos_prev) / T;
    p->v_lo = fmax(p->v_out - lim->acc_max * T, -lim->vel_max);
    p->v_hi = fmin(p->v_out + lim->acc_max * T, lim->vel_max);
    p->p_lo = y + p->v_lo * T;
    p->p_hi = y + p->v_hi * T;
    double t_hi = fabs(p->v_hi) / lim->acc_max + T, t_lo = fabs(p->v_lo) / lim->acc_max + T;
    double s_hi = y + (p->v_hi / 2) * t_hi, s_lo = y + (p->v_lo / 2) * t_lo;
    double m_hi = fabs((p->v_in - p->v_hi) / lim->acc_max) - T;
    double m_lo = fabs((p->v_in - p->v_lo) / lim->acc_max) - T;
    double o_hi = p->p_hi + ((p->v_hi + p->v_in) / 2) * m_hi;
    double o_lo = p->p_lo + ((p->v_lo + p->v_in) / 2) * m_lo;
    double i_hi = x + p->v_in * m_hi, i_lo = x + p->v_in * m_lo;
    int max_reachable = p->p_lo <= lim->pos_max && lim->pos_max <= p->p_hi;
    int min_reachable = p->p_lo <= lim->pos_min && lim->pos_min <= p->p_hi;
    p->dv = -p->v_out;
    p->a_lo = s_lo;
    p->a_hi = s_hi;
    if (s_hi > lim->pos_max + LIMIT3_EPS && !max_reachable)
        limit3_goal_limit(p, lim->pos_max);
    else if (s_lo < lim->pos_min - LIMIT3_EPS && !min_reachable)
        limit3_goal_limit(p, lim->pos_min);
    else if (x >= lim->pos_max && i_hi > o_hi)
        limit3_goal_limit(p, lim->pos_max);
    else if (x <= lim->pos_min && i_lo < o_lo)
        limit3_goal_limit(p, lim->pos_min);
    else {
        p->g_lo = i_lo;
        p->g_hi = i_hi;
        p->g_cur = x;
        p->g_prev = st->target_prev;
        p->dv = p->v_out - p->v_in;
        p->a_lo = o_lo;
        p->a_hi = o_hi;
    }
}

/* Land on the goal over a few periods with a constant acceleration. */
static inline double limit3_smooth(const limit3_plan_t *p, double y, double t, double T)
{
    double sg = t >= 0 ? 1.0 : -1.0;
    double ti = trunc((t - LIMIT3_EPS * sg) / T + sg) * T;
    double a = p->dv / ti;
    double v = p->v_out + a * T;
    return fmin(p->p_hi, fmax(p->p_lo, y + v * T));
}

/* Choose this period's output from the plan (lock on, accelerate, smooth, brake or coast). */
static inline double limit3_choose(const limit3_plan_t *p, const limit3_state_t *st,
                                   const limit3_limits_t *lim, double T)
{
    double y = st->pos;
    double pd = y - p->g_prev;
    double t = fabs(p->dv) < LIMIT3_EPS ? 0.0 : pd / (p->dv / 2);
    if (p->p_lo <= p->g_cur && p->g_cur <= p->p_hi && fabs(t) <= T)
        return p->g_cur;
    if (p->a_hi < p->g_hi + LIMIT3_EPS)
        return p->p_hi;
    if (p->a_lo > p->g_lo - LIMIT3_EPS)
        return p->p_lo;
    if (fabs(t) < T * lim->smooth_periods)
        return limit3_smooth(p, y, t, T);
    if (p->g_hi + LIMIT3_EPS < p->a_hi && p->g_prev > y)
        return p->p_lo;
    if (p->g_lo - LIMIT3_EPS > p->a_lo && p->g_prev < y)
        return p->p_hi;
    return (p->p_lo + p->p_hi) / 2;
}

/* One period: x is the target (in, or 0 when disabled); T the period in seconds. */
static inline void limit3_step(limit3_state_t *st, const limit3_limits_t *lim,
                               double x, int load, double T)
{
    if (x != x)
        x = st->target_prev; /* a NaN target holds the previous one */
    else if (isinf(x))
        x = x > 0 ? lim->pos_max : lim->pos_min; /* an infinite target means the limit, not a run away */
    if (load) {
        limit3_commit(st, fmin(lim->pos_max, fmax(lim->pos_min, x)), 0.0);
        st->target_prev = st->pos;
        return;
    }
    limit3_plan_t p;
    limit3_plan(&p, st, lim, x, T);
    double y = limit3_choose(&p, st, lim, T);
    if (!isfinite(y))
        y = st->pos; /* zero or NaN limits: hold rather than output NaN */
    limit3_commit(st, y, x);
}

#endif
