/* tp_exec.c: moving along the path for one cycle: go as fast as allowed, switch to braking at the last safe instant. */
#include <math.h>
#include "tp_internal.h"

/* Bisection steps for the switch time (2^-36 of a cycle: far below a nanometre at any speed). */
#define TP_SWITCH_ITER 36
/* Targets checked at once: the nearest and the two after it. */
#define TP_CHECK_TARGETS 3
/* Later targets a carried acceleration is checked against at most. */
#define TP_MOMENTUM_TARGETS 8
/* Sub-steps per cycle (target crossings); a cycle never loops for ever. */
#define TP_SUBSTEPS (2 * TP_WINDOW_MAX + 4)

/* Slack on distances compared for safety: rounding of the closed forms. */
static double slack(double d)
{
    return 1e-9 * (1.0 + fabs(d));
}

/* Distance a positive acceleration needs to settle to zero (jerk-limited). */
static double settle_dist(const tp_state1_t *st, const tp_lim1_t *lim)
{
    if (st->a <= 0.0 || lim->jerk <= 0.0)
        return 0.0;
    double t = st->a / lim->jerk;
    return st->v * t + 0.5 * st->a * t * t - lim->jerk * t * t * t / 6.0;
}

/* Settling a positive acceleration right away, with the smallest jerk of the stretches it
 * crosses: where it ends (*x, a position) and the speed it ends at; the first target at or after
 * *x in *m.  -1 when a target crossed on the way is slower than that speed (loose: accepting the
 * current state tolerates rounding). */
static double settle_now(const tp_window_t *w, int k, double s, const tp_state1_t *st, double loose,
                         double *x, int *m)
{
    tp_lim1_t lim = w->t[k].lim;
    double v_end = st->v, end = s;
    int n = k;
    for (int it = 0; it < TP_MOMENTUM_TARGETS; it++) {
        v_end = st->v + st->a * st->a / (2.0 * lim.jerk);
        end = s + settle_dist(st, &lim);
        n = k;
        int grew = 0;
        while (n < w->n && w->t[n].s < end) {
            if (v_end > w->t[n].v * (1.0 + 1e-10 + loose * 1e-8) + 1e-12)
                return -1.0;
            /* crossing a target still accelerating: no faster than the span after it allows */
            if (n + 1 < w->n && st->a > w->t[n + 1].lim.acc * (1.0 + loose * 1e-9))
                return -1.0;
            n++;
            if (n < w->n && w->t[n].lim.jerk > 0.0 && w->t[n].lim.jerk < lim.jerk) {
                lim.jerk = w->t[n].lim.jerk;
                grew = 1;
            }
        }
        if (!grew)
            break;
    }
    *x = end;
    *m = n;
    return v_end;
}

/* A state still accelerating towards a faster target k may reach it before the acceleration has
 * settled and carry it on; the backward pass only promised the later targets from target k at rest
 * acceleration.  Fine when braking is needed anyway (the brake ends at rest acceleration on target
 * k), when the acceleration settles before target k, or when, settled right away, the state is
 * within the backward pass's speed curve of the target after the settling. */
static int momentum_ok(const tp_window_t *w, int k, double s, const tp_state1_t *st, double loose)
{
    const tp_target_t *tk = &w->t[k];
    if (st->a <= 0.0 || tk->lim.jerk <= 0.0)
        return 1;
    if (st->v + st->a * st->a / (2.0 * tk->lim.jerk) > tk->v)
        return 1;
    if (settle_dist(st, &tk->lim) <= tk->s - s + loose * slack(tk->s))
        return 1;
    double x;
    int m;
    double v_end = settle_now(w, k, s, st, loose, &x, &m);
    if (v_end < 0.0)
        return 0;
    if (m >= w->n)
        return 1;
    const tp_target_t *tm = &w->t[m];
    return v_end <= tp_chain_vmax(tm->v, tm->s - x, &tm->lim) * (1.0 + loose * 1e-9);
}

/* A state standing on target k carries its acceleration into the span after it: no more than that
 * span allows, and settled with its jerk without passing the target's speed. */
static int crossing_ok(const tp_window_t *w, int k, const tp_state1_t *cur, double loose)
{
    if (cur->a <= 0.0 || k + 1 >= w->n)
        return 1;
    const tp_lim1_t *next = &w->t[k + 1].lim;
    if (cur->a > next->acc * (1.0 + loose * 1e-9))
        return 0;
    if (!(next->jerk > 0.0))
        return 1;
    double v_end = cur->v + cur->a * cur->a / (2.0 * next->jerk);
    return v_end <= w->t[k].v * (1.0 + 1e-10 + loose * 1e-8) + 1e-12;
}

/* Can the state st (st.s into the sub-step from s_now) still meet the targets?  The nearest target
 * must be reachable; the backward pass made the later ones reachable from it at rest acceleration,
 * so a state that would carry acceleration into a later, slower target settles it first.  When
 * standing on a target the next one is checked from there. */
static int safe_at(const tp_window_t *w, int ti, double s_now, const tp_state1_t *st, double loose)
{
    double s = s_now + st->s;
    tp_state1_t cur = *st;
    for (int k = ti; k < w->n && k < ti + TP_CHECK_TARGETS; k++) {
        const tp_target_t *t = &w->t[k];
        double rem = t->s - s, sl = slack(t->s);
        if (rem < -sl)
            return 0;
        /* accepting the current state tolerates rounding of the speed the profile rides at */
        double need = tp_brake_dist(cur.v, cur.a, t->v * (1.0 + loose * 1e-9), &t->lim);
        if (rem <= 1e-6 + 1e-9 * fabs(t->s)) {
            if (need > rem + sl)
                return 0;
            /* on this target: the next one counts from it, at no more than its speed (what is
             * left before it is braked with its own limits) */
            s = fmax(s, t->s);
            cur.v = fmin(cur.v, t->v);
            if (!crossing_ok(w, k, &cur, loose))
                return 0;
            continue;
        }
        return need <= rem + loose * sl && momentum_ok(w, k, s, &cur, loose);
    }
    return 1;
}

/* Move the executor state along by a profile for dt seconds. */
static void advance(tp_planner_t *tp, const tp_prof_t *p, double dt)
{
    tp_state1_t st = tp_prof_at(p, dt);
    tp->ex.s += st.s;
    tp->ex.v = st.v > 0.0 ? st.v : 0.0;
    tp->ex.a = st.v > 0.0 || st.a > 0.0 ? st.a : 0.0;
}

/* Largest time in [0, hi] at which the go profile is still safe (hi itself not safe). */
static double switch_time(const tp_window_t *w, int ti, double s_now, const tp_prof_t *go, double hi)
{
    double lo = 0.0;
    for (int k = 0; k < TP_SWITCH_ITER; k++) {
        double mid = 0.5 * (lo + hi);
        tp_state1_t st = tp_prof_at(go, mid);
        if (safe_at(w, ti, s_now, &st, 0.0))
            lo = mid;
        else
            hi = mid;
        if (hi - lo <= 1e-17)
            break;
    }
    return lo;
}

/* Brake towards target t (with the limits lim) for up to t_rem seconds; returns the time used
 * (less when t is reached). */
static double brake(tp_planner_t *tp, const tp_target_t *t, const tp_lim1_t *lim, double vt,
                    double t_rem, int *reached)
{
    tp_prof_t b;
    double s_now = tp->ex.s;
    tp_prof_velocity(&b, tp->ex.v, tp->ex.a, vt, lim);
    *reached = 0;
    if (t->stop || t->v <= 0.0) {
        double dur = tp_prof_duration(&b);
        if (dur <= t_rem) {
            double end = s_now + tp_prof_length(&b);
            /* the brake was aimed at the stop: land on it exactly (the miss is rounding) */
            tp->ex.s = end > t->s - 1e-6 - 1e-9 * fabs(t->s) ? t->s : end;
            tp->ex.v = tp->ex.a = 0.0;
            *reached = tp->ex.s == t->s;
            return t_rem;
        }
        advance(tp, &b, t_rem);
        return t_rem;
    }
    double tc = tp_prof_time_at(&b, t->s - s_now);
    if (tc <= t_rem) {
        advance(tp, &b, tc);
        tp->ex.s = fmax(tp->ex.s, t->s);
        *reached = 1;
        return tc;
    }
    advance(tp, &b, t_rem);
    return t_rem;
}

/* The speed change of a stretch.  Its jerk anticipates the stretches ahead; when that would let the
 * acceleration already under way overshoot the cap or drive the speed below zero, the stretch's
 * own (larger) jerk settles it instead. */
static void go_profile(tp_prof_t *go, double v, double a, const tp_stretch_t *st)
{
    tp_prof_velocity(go, v, a, st->v, &st->lim);
    double j = st->lim.jerk;
    if (!(j > 0.0) || !(st->jerk_own > j))
        return;
    tp_lim1_t own = {st->lim.acc, st->jerk_own};
    tp_prof_t settle;
    double v_own = v + a * fabs(a) / (2.0 * st->jerk_own);
    /* braking: settle the deceleration with the own (larger) jerk, the quickest way back to speed */
    if (a < 0.0 && v_own >= 0.0) {
        tp_prof_velocity(&settle, v, a, v_own, &own);
        if (settle.n > 0 && settle.ph[0].j > 0.0)
            *go = settle;
        return;
    }
    double v_rest = v + a * fabs(a) / (2.0 * j);
    if ((a > 0.0 && v_rest > st->v * (1.0 + 1e-6)) || (a < 0.0 && v_rest < 0.0)) {
        tp_prof_velocity(&settle, v, a, st->v, &own);
        /* only to settle (bring the acceleration towards zero first), never to push harder: when
         * the own profile would push first, just settle with the own jerk and go on next cycle */
        if (!(settle.n > 0 && settle.ph[0].j * a < 0.0))
            tp_prof_velocity(&settle, v, a, v_own, &own);
        if (settle.n > 0 && settle.ph[0].j * a < 0.0)
            *go = settle;
    }
}

/* Stretch index after crossing boundaries up to the executor position. */
static int stretch_at(const tp_window_t *w, int ri, double s)
{
    while (ri + 1 < w->nr && s >= w->r[ri + 1].s)
        ri++;
    return ri;
}

/* One sub-step: go within the current stretch until a target, a boundary or the end of the time;
 * switch to braking at the last safe instant.  Returns 1 when the executor rests on a stop. */
static int substep(tp_planner_t *tp, const tp_window_t *w, int *ti, int *ri, double *t_rem)
{
    const tp_target_t *t = &w->t[*ti];
    const tp_stretch_t *st = &w->r[*ri];
    double s_now = tp->ex.s;
    if (t->s - s_now <= slack(t->s) && (t->stop || t->v <= 0.0) && tp->ex.v <= 0.0) {
        tp->ex.s = fmax(tp->ex.s, t->s);   /* resting on the stop: exactly on it */
        tp->ex.a = 0.0;
        return 1;
    }
    tp_prof_t go;
    go_profile(&go, tp->ex.v, tp->ex.a, st);
    double tc = tp_prof_time_at(&go, t->s - s_now);
    double tb = *ri + 1 < w->nr ? tp_prof_time_at(&go, w->r[*ri + 1].s - s_now) : INFINITY;
    double hi = fmin(*t_rem, fmin(tc, tb));
    tp_state1_t sh = tp_prof_at(&go, hi);
    if (safe_at(w, *ti, s_now, &sh, 0.0)) {
        advance(tp, &go, hi);
        *t_rem -= hi;
        if (hi >= tc) {
            tp->ex.s = fmax(tp->ex.s, t->s);
            if (t->stop || t->v <= 0.0) {
                tp->ex.s = t->s;        /* arrived at rest on a stop */
                tp->ex.v = tp->ex.a = 0.0;
                return 1;
            }
            (*ti)++;
        }
        if (hi >= tb)
            tp->ex.s = fmax(tp->ex.s, w->r[*ri + 1].s);
        *ri = stretch_at(w, *ri, tp->ex.s);
        return 0;
    }
    tp_state1_t s0 = {0.0, tp->ex.v, tp->ex.a};
    if (safe_at(w, *ti, s_now, &s0, 1.0)) {
        double ts = switch_time(w, *ti, s_now, &go, hi);
        advance(tp, &go, ts);
        *t_rem -= ts;
    } else {
        tp->emergencies++;
    }
    int reached;
    double vt = fmin(t->v, st->v);    /* braking never speeds up past the stretch's cap */
    if (tp->ex.a > 0.0 && t->lim.jerk > 0.0) {
        double v_rest = tp->ex.v + tp->ex.a * tp->ex.a / (2.0 * t->lim.jerk);
        vt = fmin(vt, v_rest);          /* settle the acceleration, never speed up while braking */
    }
    *t_rem -= brake(tp, t, &t->lim, vt, *t_rem, &reached);
    *ri = stretch_at(w, *ri, tp->ex.s);
    if (reached && t->v > 0.0)
        (*ti)++;
    return reached && t->v <= 0.0;
}

/* First target not behind the executor. */
static int first_target(const tp_window_t *w, double s)
{
    int ti = 0;
    while (ti < w->n && w->t[ti].s < s - slack(w->t[ti].s))
        ti++;
    return ti;
}

/* The executor's current state can still meet the window's targets. */
int tp_exec_safe(const tp_planner_t *tp, const tp_window_t *w)
{
    tp_state1_t st = {0.0, tp->ex.v, tp->ex.a};
    int ti = first_target(w, tp->ex.s);
    return ti >= w->n || safe_at(w, ti, tp->ex.s, &st, 1.0);
}

/* Run the executor for dt seconds against the window. */
void tp_exec_move(tp_planner_t *tp, const tp_window_t *w, double dt)
{
    double t_rem = dt;
    int ti = first_target(w, tp->ex.s), ri = 0;
    for (int step = 0; step < TP_SUBSTEPS && t_rem > 0.0 && ti < w->n; step++)
        if (substep(tp, w, &ti, &ri, &t_rem))
            break;
}

/* Advance the element and region pointers to the executor position. */
void tp_exec_locate(tp_planner_t *tp)
{
    while (tp->ex.elem + 1 < tp->elem_head && tp->ex.s >= tp_elem_at(tp, tp->ex.elem + 1)->s0)
        tp->ex.elem++;
    while (tp->ex.reg + 1 < tp->reg_head && tp->ex.s >= tp_reg_at(tp, tp->ex.reg + 1)->s0)
        tp->ex.reg++;
}

/* Commanded position at the executor's place on the path. */
tp_vec_t tp_exec_position(tp_planner_t *tp)
{
    if (tp->ex.elem >= tp->elem_head)
        return tp->pos;
    const tp_elem_t *e = tp_elem_at(tp, tp->ex.elem);
    const tp_geo_t *g = tp_elem_geo(tp, e);
    double u = e->u0 + (tp->ex.s - e->s0);
    if (tp->ex.s >= e->s0 + e->len)
        u = e->u0 + e->len;
    if (u >= g->len * (1.0 - 1e-12))
        u = g->len;                     /* the exact end point, not a rounding short of it */
    return tp_geo_eval(g, u);
}
