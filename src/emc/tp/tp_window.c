/* tp_window.c: the lookahead: region caps ahead, reduced to the binding speed targets by a backward pass. */
#include <math.h>
#include "tp_internal.h"

/* The window reaches this many stopping distances ahead. */
#define TP_WINDOW_REACH 2.0

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

/* Speed on the braking curve into (v, lim) at distance d, covering any acceleration there. */
static double curve_plus(double v, double d, const tp_lim1_t *lim)
{
    if (lim->jerk > 0.0) {
        double tr = lim->acc / lim->jerk;
        double d_ramp = v * tr + lim->jerk * tr * tr * tr / 6.0;
        if (d < d_ramp)
            d = d_ramp;
    }
    return tp_brake_curve(v, d, lim);
}

/* A valley: the speed allowed at a region start and the limits of the stretch before it. */
typedef struct valley {
    double s, v;
    tp_lim1_t lim;
    int stop;
} valley_t;

/* The stretch before a valley allows clearly more than the span after it. */
static int lim_stronger(const tp_lim1_t *before, const tp_lim1_t *span)
{
    if (before->acc > 1.25 * span->acc)
        return 1;
    return span->jerk > 0.0 && before->jerk > 1.25 * span->jerk;
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
            rev[m].v = fmin(vl[k].v, tp_chain_vmax(vb, d, &span));
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

/* Limits of a region as a pair. */
static tp_lim1_t reg_lim(const tp_region_t *r)
{
    tp_lim1_t l = {r->a, r->j};
    return l;
}

/* Note a region the cycle may enter; acc is the smallest acceleration cap ahead of it. */
static void add_stretch(tp_window_t *w, double s0, double cap, const tp_region_t *r)
{
    if (w->nr >= TP_CROSS_MAX)
        return;
    w->r[w->nr].s = s0;
    w->r[w->nr].v = cap;
    w->r[w->nr].lim.acc = r->a;
    w->r[w->nr].lim.jerk = r->j;
    w->nr++;
}

/* Lower the acceleration of every stretch to a cap met within the anticipation distance. */
static void anticipate(tp_window_t *w, double s0, double acc)
{
    for (int k = 0; k < w->nr; k++)
        if (w->r[k].s <= s0)
            w->r[k].lim.acc = fmin(w->r[k].lim.acc, acc);
}

/* Build the window from the executor state: speed targets, and the stretches of the next cycle. */
void tp_window_build(tp_planner_t *tp, tp_window_t *w, double fs, double rs, double spindle_rps)
{
    valley_t vl[TP_WINDOW_MAX + 1];
    int n = 0;
    double s = tp->ex.s, T = tp->lim.cycle_time;
    const tp_region_t *cur = tp_reg_at(tp, tp->ex.reg);
    tp_lim1_t lim_cur = reg_lim(cur);
    double cap_cur = tp_region_cap(tp, cur, fs, rs, spindle_rps);
    w->nr = 0;
    add_stretch(w, s, cap_cur, cur);
    double v = fmax(tp->ex.v, fmin(cap_cur, 1e9));
    double travel = (v + lim_cur.acc * T) * T * 1.5 + 1e-12;
    double ramp = lim_cur.jerk > 0.0 ? v * (fabs(tp->ex.a) + lim_cur.acc) / lim_cur.jerk * 1.5 : 0.0;
    double reach = TP_WINDOW_REACH * tp_stop_dist(v, fabs(tp->ex.a), &lim_cur) + 4.0 * travel;
    /* the window only grows: a pseudo stop that moved closer could make a safe state unsafe */
    if (tp->ex.window_end - s > reach)
        reach = tp->ex.window_end - s;
    tp->ex.window_end = s + reach;
    tp_lim1_t before = lim_cur;
    uint64_t k;
    for (k = tp->ex.reg + 1; k < tp->reg_head && n < TP_WINDOW_MAX; k++) {
        const tp_region_t *r = tp_reg_at(tp, k);
        double d = r->s0 - s;
        double rcap = tp_region_cap(tp, r, fs, rs, spindle_rps), cap = fmin(rcap, r->v_start);
        if (d < travel)
            add_stretch(w, r->s0, rcap, r);
        if (d < travel + ramp)
            anticipate(w, r->s0, r->a);
        vl[n].s = r->s0;
        vl[n].v = cap;
        vl[n].lim = before;
        vl[n].stop = cap <= 0.0;
        n++;
        before = reg_lim(r);
        if (d > reach)
            break;
    }
    if (k >= tp->reg_head) {
        /* end of the known path: a stop there */
        const tp_region_t *last = tp_reg_at(tp, tp->reg_head - 1);
        vl[n].s = last->s0 + last->len;
        vl[n].v = 0.0;
        vl[n].lim = before;
        vl[n].stop = 1;
        n++;
    } else {
        vl[n - 1].v = 0.0;              /* beyond the reach: a pseudo stop bounds the pass */
        vl[n - 1].stop = 0;
    }
    reduce(w, vl, n, lim_cur);
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
