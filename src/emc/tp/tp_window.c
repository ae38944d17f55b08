/* tp_window.c: the lookahead: region caps ahead, reduced to the binding speed targets by a backward pass. */
#include <math.h>
#include "tp_internal.h"

/* The window reaches this many stopping distances ahead. */
#define TP_WINDOW_REACH 2.0
/* A valley where the limits drop by more than this factor stays a target (trapezoid, S-curve). */
#define TP_LIM_STRONGER 1.01
#define TP_LIM_STRONGER_JERK 2.0

/* Speed a region allows now: machine cap, requested speeds times the overrides, spindle sync. */
double tp_region_cap(const tp_planner_t *tp, const tp_region_t *r, double feed_scale,
                     double rapid_scale, double spindle_rps)
{
    double v = r->v_mach;
    (void)tp;
    if (r->flags & (TP_REG_SYNC_POS | TP_REG_TAP))
        return v;
    if (r->flags & TP_REG_SYNC_VEL)
        return fmin(v, r->sync_k * fabs(spindle_rps) * feed_scale);
    if (isfinite(r->v_feed))
        v = fmin(v, r->v_feed * feed_scale);
    if (isfinite(r->v_rapid))
        v = fmin(v, r->v_rapid * rapid_scale);
    return v;
}

/* Smaller of two tangential limit pairs (jerk 0 = unlimited). */
static tp_lim1_t lim_min(tp_lim1_t a, double acc, double jerk)
{
    tp_lim1_t r = a;
    r.acc = fmin(a.acc, acc);
    if (jerk > 0.0)
        r.jerk = a.jerk > 0.0 ? fmin(a.jerk, jerk) : jerk;
    return r;
}

/* Largest speed any state (any acceleration) can have at distance d before a target of speed v and
 * still meet it: decelerating at the full acceleration already, the target may be met with the
 * acceleration still negative, so no final jerk ramp is needed. */
static double curve_plus(double v, double d, const tp_lim1_t *lim)
{
    return sqrt(v * v + 2.0 * lim->acc * d);
}

/* A valley: the speed allowed at a region start and the limits of the stretch before it. */
typedef struct valley {
    double s, v;
    double cap;                 /* the region's own cap (v is INFINITY where it limits nothing) */
    tp_lim1_t lim;
    int stop;
} valley_t;

/* The stretch before a valley allows clearly more than the span after it.  Without jerk limits
 * every drop counts: the accelerations of curved regions grow as the speed bound ahead falls, and
 * a target dropped in one cycle and kept in the next would leave a state planned on it unsafe. */
static int lim_stronger(const tp_lim1_t *before, const tp_lim1_t *span)
{
    if (!(span->jerk > 0.0))
        return before->acc > TP_LIM_STRONGER * span->acc;
    if (before->acc > TP_LIM_STRONGER_JERK * span->acc)
        return 1;
    return before->jerk > TP_LIM_STRONGER_JERK * span->jerk;
}

/* Backward pass: keep the valleys that bind, lowered so that each can reach the next at rest
 * acceleration; a valley where the limits drop also becomes a target, so that braking before it
 * may use the larger limits. */
static void reduce(tp_window_t *w, const valley_t *vl, int n, tp_lim1_t first_lim)
{
    tp_target_t rev[TP_WINDOW_MAX];
    int m = 0, b = n - 1;
    tp_lim1_t span = vl[b].lim;
    rev[m].s = vl[b].s;
    rev[m].v = vl[b].v;
    rev[m].stop = vl[b].stop;
    m++;
    for (int k = n - 2; k >= 0; k--) {
        double d = vl[b].s - vl[k].s;
        double vb = rev[m - 1].v;
        int bind = vl[k].v < curve_plus(vb, d, &span);
        if ((bind || lim_stronger(&vl[k].lim, &span)) && m < TP_WINDOW_MAX) {
            rev[m - 1].lim = span;
            rev[m].s = vl[k].s;
            rev[m].v = fmin(fmin(vl[k].v, vl[k].cap), tp_chain_vmax(vb, d, &span));
            rev[m].stop = vl[k].stop && rev[m].v <= 0.0;
            m++;
            b = k;
            span = vl[k].lim;
        } else {
            span = lim_min(span, vl[k].lim.acc, vl[k].lim.jerk);
        }
    }
    span = lim_min(span, first_lim.acc, first_lim.jerk);
    rev[m - 1].lim = span;
    w->n = m;
    for (int k = 0; k < m; k++)
        w->t[k] = rev[m - 1 - k];
}

/* Limits of a region as a pair, for speeds up to v_hi: a curved region leaves more acceleration
 * for speed changes the slower it is passed. */
static tp_lim1_t reg_lim(const tp_region_t *r, double v_hi)
{
    tp_lim1_t l = {r->a, r->j};
    if (r->a_rest > r->a && v_hi < r->v_mach) {
        double f = v_hi / r->v_mach;
        l.acc = r->a + (r->a_rest - r->a) * (1.0 - f * f);
    }
    return l;
}

/* Fastest the executor can ever be at the far end of a region it enters at most at speed
 * sqrt(vf2) after dist of it: no region lets it accelerate more than its a_rest.  The bound only
 * falls from cycle to cycle, so the limits reg_lim gives only grow: plans stay valid. */
static double reach_speed(const tp_region_t *r, double vf2, double dist)
{
    return fmin(r->v_mach, sqrt(vf2 + 2.0 * fmax(r->a_rest, r->a) * fmax(dist, 0.0)));
}

/* Note a region the cycle may enter, with its limits for speeds up to v_hi. */
static void add_stretch(tp_window_t *w, double s0, double cap, const tp_region_t *r, double v_hi)
{
    if (w->nr >= TP_CROSS_MAX)
        return;
    w->r[w->nr].s = s0;
    w->r[w->nr].v = cap;
    w->r[w->nr].lim = reg_lim(r, v_hi);
    w->r[w->nr].jerk_own = r->j;
    w->nr++;
}

/* Lower the acceleration and jerk of every stretch to caps met within the anticipation distance:
 * an acceleration carried into a stretch of smaller jerk settles later and would overshoot. */
static void anticipate(tp_window_t *w, double s0, double acc, double jerk)
{
    for (int k = 0; k < w->nr; k++)
        if (w->r[k].s <= s0) {
            w->r[k].lim.acc = fmin(w->r[k].lim.acc, acc);
            if (jerk > 0.0)
                w->r[k].lim.jerk = w->r[k].lim.jerk > 0.0 ? fmin(w->r[k].lim.jerk, jerk) : jerk;
        }
}

/* A region to anticipate: where it starts, the limits to anticipate, and whether settling the
 * acceleration the cycle may end with, with its jerk, would reach it. */
typedef struct ant {
    double s;
    tp_lim1_t lim;
    int settle_reaches;
} ant_t;

/* Anticipate the regions noted in ant that lie before the first speed target.  From that target on
 * the targets' limits bind a state approaching: the executor brakes onto a target at rest
 * acceleration, or crosses it with no more acceleration than the span after it allows and settles
 * it with that span's jerk (momentum_ok); anticipating those regions as well would hold back the
 * speed-up all the way to them.  Only their smaller jerk is anticipated once settling the
 * acceleration under way would reach them: a brake begun just before a target may still carry
 * acceleration across it. */
static void anticipate_untargeted(tp_window_t *w, const ant_t *ant, int na, double s)
{
    int ti = 0;                         /* a target the executor stands on is behind it */
    while (ti < w->n && w->t[ti].s - s <= 1e-6 + 1e-9 * fabs(w->t[ti].s))
        ti++;
    for (int k = 0; k < na; k++) {
        if (ti >= w->n || ant[k].s < w->t[ti].s)
            anticipate(w, ant[k].s, ant[k].lim.acc, ant[k].lim.jerk);
        else if (ant[k].settle_reaches)
            anticipate(w, ant[k].s, INFINITY, ant[k].lim.jerk);
    }
}

/* How far settling acceleration a_pos with jerk j takes, at the speed the executor can reach by
 * then (from v_now, accelerating at most at a_most, never above v), with a margin of 1.5. */
static double settle_reach(double a_pos, double j, double v, double v_now, double a_most, double T)
{
    double t = a_pos / j;
    return 1.5 * (fmin(v, v_now + a_most * (T + t)) + a_pos * T) * t;
}

/* Acceleration from which the executor can still settle to lim_r's before a region dist ahead
 * (what the cycle travels already taken off): at most the settling time (jerk of the smaller of
 * the two limits) times the speed it can reach by then (from v_now, accelerating at most at a_most,
 * never above v), with a margin of 1.5.  Near the region it is the region's own acceleration; far
 * from it the executor keeps its own. */
static double settle_acc(const tp_lim1_t *lim_cur, const tp_lim1_t *lim_r, double dist, double v,
                         double v_now, double a_most, double T)
{
    double j = lim_r->jerk > 0.0 && lim_cur->jerk > 0.0 ? fmin(lim_r->jerk, lim_cur->jerk) : 0.0;
    if (!(j > 0.0) || !(dist > 0.0))
        return lim_r->acc;
    double t_settle = (a_most + lim_cur->acc) / j;
    double v_settle = fmin(v, v_now + a_most * (T + t_settle));
    if (!(v_settle > 0.0))
        return lim_cur->acc;
    return lim_r->acc + j * dist / (1.5 * v_settle);
}

/* A region the executor meets walking in direction dir: where it enters it (backwards positions
 * are -s), whether a stop lies at that point, whether it may enter at all (reverse run cannot run
 * synchronised or tapping moves backwards). */
typedef struct meet {
    const tp_region_t *r;
    double pos;
    int stop;
    int blocked;
} meet_t;

/* The k-th region after the current one in direction dir; 0 past the end of the kept path. */
static int meet_region(tp_planner_t *tp, int dir, uint64_t k, meet_t *m)
{
    if (dir > 0) {
        uint64_t n = tp->ex.reg + k;
        if (n >= tp->reg_head)
            return 0;
        m->r = tp_reg_at(tp, n);
        m->pos = m->r->s0;
        m->stop = m->r->v_start <= 0.0;
        m->blocked = 0;
        return 1;
    }
    if (tp->ex.reg < tp->reg_tail + k)
        return 0;
    uint64_t n = tp->ex.reg - k;
    m->r = tp_reg_at(tp, n);
    m->pos = -(m->r->s0 + m->r->len);
    m->stop = (tp_reg_at(tp, n + 1)->flags & TP_REG_STOP) != 0;
    m->blocked = (m->r->flags & (TP_REG_SYNC_POS | TP_REG_TAP)) != 0;
    return 1;
}

/* Where the kept path ends in direction dir: after the last region met (the current one when none
 * was met). */
static double path_end(tp_planner_t *tp, int dir, const meet_t *last, int have_last)
{
    if (dir > 0) {
        const tp_region_t *r = tp_reg_at(tp, tp->reg_head - 1);
        return r->s0 + r->len;
    }
    return -(have_last ? last->r->s0 : tp_reg_at(tp, tp->ex.reg)->s0);
}

/* Build the window from the executor state for direction dir (positions -s backwards): speed
 * targets, and the stretches of the next cycle. */
void tp_window_build(tp_planner_t *tp, tp_window_t *w, double fs, double rs, double spindle_rps, int dir)
{
    valley_t vl[TP_WINDOW_MAX + 1];
    ant_t ant[TP_WINDOW_MAX];           /* regions to anticipate */
    int n = 0, na = 0;
    double s = dir > 0 ? tp->ex.s : -tp->ex.s, T = tp->lim.cycle_time;
    const tp_region_t *cur = tp_reg_at(tp, tp->ex.reg);
    double cur_end = dir > 0 ? cur->s0 + cur->len : -cur->s0;
    double v_hi = reach_speed(cur, tp->ex.v * tp->ex.v, cur_end - s);
    tp_lim1_t lim_cur = reg_lim(cur, v_hi);
    double cap_cur = tp_region_cap(tp, cur, fs, rs, spindle_rps);
    w->nr = 0;
    add_stretch(w, s, cap_cur, cur, v_hi);
    double v = fmax(tp->ex.v, fmin(cap_cur, 1e9));
    double travel = (v + lim_cur.acc * T) * T * 1.5 + 1e-12;
    double ramp = lim_cur.jerk > 0.0 ? v * (fabs(tp->ex.a) + lim_cur.acc) / lim_cur.jerk * 1.5 : 0.0;
    double v_now = tp->ex.v, a_most = fmax(fmax(tp->ex.a, 0.0) + lim_cur.jerk * T, lim_cur.acc);
    /* the most positive acceleration the cycle can end with, and how far settling it takes per
     * unit of the jerk it settles with */
    double a_pos = fmax(tp->ex.a, 0.0) + lim_cur.jerk * T;
    double settle_j = (v + a_pos * T) * a_pos * 1.5;
    double reach = TP_WINDOW_REACH * tp_stop_dist(v, fabs(tp->ex.a), &lim_cur) + 4.0 * travel;
    /* the window only grows: a pseudo stop that moved closer could make a safe state unsafe */
    if (dir > 0 && tp->ex.window_end - s > reach)
        reach = tp->ex.window_end - s;
    if (dir > 0)
        tp->ex.window_end = s + reach;
    tp_lim1_t before = lim_cur;
    /* a region start limits nothing unless its cap is below every speed allowed before it */
    double v_before = fmax(tp->ex.v, cap_cur);
    meet_t m = {NULL, 0.0, 0, 0};
    int have = 0, more;
    uint64_t k = 1;
    for (; (more = meet_region(tp, dir, k, &m)) && !m.blocked && n < TP_WINDOW_MAX; k++) {
        const tp_region_t *r = m.r;
        have = 1;
        double d = m.pos - s;
        double rcap = tp_region_cap(tp, r, fs, rs, spindle_rps), cap = m.stop ? 0.0 : rcap;
        double limit = cap < v_before ? cap : INFINITY;
        v_before = fmax(v_before, rcap);
        v_hi = reach_speed(r, v_hi * v_hi, r->len);
        tp_lim1_t lim_r = reg_lim(r, v_hi);
        if (d < travel)
            add_stretch(w, m.pos, rcap, r, v_hi);
        /* a region of smaller jerk is anticipated from as far as settling an acceleration under way
         * takes with its jerk */
        double settle = lim_r.jerk > 0.0 && lim_r.jerk < lim_cur.jerk ? settle_j / lim_r.jerk : 0.0;
        if (d < travel + fmax(ramp, settle) && na < TP_WINDOW_MAX) {
            ant[na].s = m.pos;
            ant[na].settle_reaches = settle > 0.0 && d < travel + settle_reach(a_pos, lim_r.jerk, v, v_now, a_most, T);
            ant[na].lim.acc = settle_acc(&lim_cur, &lim_r, d - travel, v, v_now, a_most, T);
            ant[na].lim.jerk = lim_r.jerk;
            na++;
        }
        vl[n].s = m.pos;
        vl[n].v = limit;
        vl[n].cap = cap;
        vl[n].lim = before;
        vl[n].stop = cap <= 0.0;
        n++;
        before = lim_r;
        if (d > reach)
            break;
    }
    if (!more || m.blocked || n == 0) {
        /* end of the kept path: a stop there */
        vl[n].s = more && m.blocked ? m.pos : path_end(tp, dir, &m, have);
        vl[n].v = vl[n].cap = 0.0;
        vl[n].lim = before;
        vl[n].stop = 1;
        n++;
    } else {
        vl[n - 1].v = vl[n - 1].cap = 0.0;  /* beyond the reach: a pseudo stop bounds the pass */
        vl[n - 1].stop = 0;
    }
    reduce(w, vl, n, lim_cur);
    anticipate_untargeted(w, ant, na, s);
}

/* Keep the executor on targets it is safe with: when the fresh targets (built from a longer view or
 * after heuristic choices in the backward pass) reject the current state while the previous ones,
 * still valid for the same path and overrides, accept it, use the previous ones this cycle. */
void tp_window_settle(tp_planner_t *tp, tp_window_t *w, double fs, double rs, double spindle_rps)
{
    int same = tp->prev.valid && tp->prev.version == tp->path_version && tp->prev.fs == fs &&
               tp->prev.rs == rs && tp->prev.spindle == spindle_rps;
    if (same && !tp_exec_safe(tp, w)) {
        tp_window_t old = *w;
        old.n = tp->prev.n;
        for (int k = 0; k < old.n; k++)
            old.t[k] = tp->prev.t[k];
        if (tp_exec_safe(tp, &old)) {
            *w = old;
            return;
        }
    }
    tp->prev.valid = 1;
    tp->prev.version = tp->path_version;
    tp->prev.fs = fs;
    tp->prev.rs = rs;
    tp->prev.spindle = spindle_rps;
    tp->prev.n = w->n;
    for (int k = 0; k < w->n; k++)
        tp->prev.t[k] = w->t[k];
}
