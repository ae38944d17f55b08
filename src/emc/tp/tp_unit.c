/* tp_unit.c: units: runs of short straight moves merged into one line within a share of the tolerance. */
#include <math.h>
#include "tp_internal.h"

/* Moves a unit may hold (bounds the work of each add). */
#define TP_UNIT_MAX 64
/* Share of the tolerance the merged line may stray from the moves' end points. */
#define TP_UNIT_TOL_SHARE 0.15
/* Without G64 P: share of the shorter neighbouring move a vertex may stray from the merged line
 * (less than the blends' quarter: shorter units leave the blends room to share whole units, so a
 * sampled curve runs curvature-continuous). */
#define TP_UNIT_FREE_SHARE 0.2
/* Without G64 P, runs merge only where every vertex turns less than this (rad). */
#define TP_UNIT_FREE_TURN 0.35

/* Head (first move) of the unit a move belongs to. */
tp_seg_t *tp_unit_head(tp_planner_t *tp, const tp_seg_t *s)
{
    return tp_seg_at(tp, s->unit);
}

/* The same requested speed.  Canon turns a feed above the machine's into the machine speed along
 * each move, which differs with the direction: such moves all ask for the most the machine allows. */
static int same_feed(const tp_segment_t *a, const tp_segment_t *b)
{
    int a_max = a->ini_maxvel > 0.0 && a->vel >= a->ini_maxvel;
    int b_max = b->ini_maxvel > 0.0 && b->vel >= b->ini_maxvel;
    return a->vel == b->vel || (a_max && b_max);
}

/* Moves that may share a unit: plain blended feed lines with the same settings. */
static int same_kind(const tp_seg_t *h, const tp_seg_t *s)
{
    const tp_segment_t *a = &h->in, *b = &s->in;
    if (h->geo.kind != TP_GEO_LINE || s->geo.kind != TP_GEO_LINE || h->geo.metric != s->geo.metric)
        return 0;
    if (a->kind != TP_SEG_LINE || b->kind != TP_SEG_LINE || b->motion_type != TP_MOTION_FEED ||
        a->motion_type != TP_MOTION_FEED)
        return 0;
    if (!same_feed(a, b) || a->enables != b->enables)
        return 0;
    if (b->atspeed || b->indexer_jnum >= 0 || a->indexer_jnum >= 0)
        return 0;
    return h->sync == TP_SYNC_NONE && s->sync == TP_SYNC_NONE && h->term == TP_TERM_COND_BLEND &&
           s->term == TP_TERM_COND_BLEND && s->tol == h->tol;
}

/* How far the merged line may pass from the end point of member k (next: the point after it).
 * With G64 P a share of P; without P the geometry bounds it, as for blends: a share of the
 * shorter neighbouring move, and only along gently turning runs (sampled curves, not corners). */
static double vertex_allowance(const tp_seg_t *h, const tp_vec_t *prev, const tp_vec_t *at,
                               const tp_vec_t *next)
{
    if (h->tol > 0.0)
        return TP_UNIT_TOL_SHARE * h->tol;
    tp_vec_t a = tp_vec_sub(at, prev), b = tp_vec_sub(next, at);
    double la = sqrt(tp_vec_dot(&a, &a)), lb = sqrt(tp_vec_dot(&b, &b));
    if (!(la > 0.0) || !(lb > 0.0) || tp_vec_dot(&a, &b) < cos(TP_UNIT_FREE_TURN) * la * lb)
        return -1.0;
    return TP_UNIT_FREE_SHARE * fmin(la, lb);
}

/* Distance from point p to the line through a with unit direction d (nine axes), and the projection. */
static double line_dist(const tp_vec_t *p, const tp_vec_t *a, const tp_vec_t *d, double *t)
{
    tp_vec_t ap = tp_vec_sub(p, a);
    *t = tp_vec_dot(&ap, d);
    tp_vec_t q = tp_vec_axpy(&ap, -*t, d);
    return sqrt(tp_vec_dot(&q, &q));
}

/* Can s join the unit headed by h (the line from h's start to s's end keeps every end point close)? */
int tp_unit_can_absorb(tp_planner_t *tp, tp_seg_t *h, const tp_seg_t *s)
{
    if (!same_kind(h, s) || h->unit_last - h->serial + 1 >= TP_UNIT_MAX)
        return 0;
    const tp_vec_t *a = &h->geo.u.line.start, *e = &s->geo.u.line.end;
    tp_vec_t d = tp_vec_sub(e, a), from = *a;
    double len = sqrt(tp_vec_dot(&d, &d)), prev = 0.0;
    if (!(len > 0.0))
        return 0;
    d = tp_vec_scale(&d, 1.0 / len);
    for (uint64_t k = h->serial; k <= h->unit_last; k++) {
        double t;
        tp_vec_t end_k = tp_vec_from_pose(&tp_seg_at(tp, k)->in.end);
        tp_vec_t next = k < h->unit_last ? tp_vec_from_pose(&tp_seg_at(tp, k + 1)->in.end) : *e;
        double limit = vertex_allowance(h, &from, &end_k, &next);
        if (line_dist(&end_k, a, &d, &t) > limit || t <= prev || t >= len)
            return 0;
        prev = t;
        from = end_k;
    }
    return 1;
}

/* The tighter of two limits, 0 meaning none. */
static double tighter(double a, double b)
{
    if (!(b > 0.0))
        return a;
    return a > 0.0 ? fmin(a, b) : b;
}

/* Merge s into the unit of h: the unit becomes the line from h's start to s's end; each move owns
 * the stretch between the projections of its end points. */
void tp_unit_absorb(tp_planner_t *tp, tp_seg_t *h, tp_seg_t *s)
{
    tp_vec_t start = h->geo.u.line.start, end = s->geo.u.line.end;
    s->unit = h->serial;
    h->unit_last = s->serial;
    tp_geo_line(&h->geo, &start, &end);
    /* the unit keeps the tighter machine speed, acceleration and jerk of its moves (canon gives
     * each move the limits along its own direction) */
    for (int i = 0; i < TP_NBOUND; i++) {
        h->lim.vel[i] = tighter(h->lim.vel[i], s->lim.vel[i]);
        h->lim.acc[i] = tighter(h->lim.acc[i], s->lim.acc[i]);
        h->lim.jerk[i] = tighter(h->lim.jerk[i], s->lim.jerk[i]);
    }
    const tp_vec_t *d = &h->geo.u.line.dir;
    double dd = tp_vec_dot(d, d), prev = 0.0, dev = 0.0;
    for (uint64_t k = h->serial; k <= h->unit_last; k++) {
        tp_seg_t *m = tp_seg_at(tp, k);
        tp_vec_t end_k = tp_vec_from_pose(&m->in.end);
        tp_vec_t ap = tp_vec_sub(&end_k, &start);
        double t = tp_vec_dot(&ap, d) / dd;
        tp_vec_t q = tp_vec_axpy(&ap, -t, d);
        dev = fmax(dev, tp_vec_dev_norm(&q));
        m->own0 = prev;
        m->own1 = k == h->unit_last ? h->geo.len : t;
        prev = m->own1;
    }
    h->unit_dev = dev;
}

/* Emit [u0, u1] of the unit's geometry, each part owned by the move it belongs to. */
void tp_unit_emit(tp_planner_t *tp, tp_seg_t *h, double u0, double u1, uint32_t flags)
{
    if (h->unit_last == h->serial) {
        tp_emit_piece(tp, h, h, 0, u0, u1, flags);
        return;
    }
    /* one line: the same caps for every move's part */
    tp_region_t tmpl;
    tp_emit_caps(tp, h, &h->geo, u0, u1, &h->lim, flags, &tmpl);
    for (uint64_t k = h->serial; k <= h->unit_last; k++) {
        tp_seg_t *m = tp_seg_at(tp, k);
        double a = fmax(u0, m->own0), b = fmin(u1, m->own1);
        if (k == h->unit_last)
            b = u1;
        if (b > a)
            tp_emit_region(tp, m, h, 0, a, b, &tmpl);
    }
}

/* The move of a unit that owns its end (the blend out of it starts there). */
tp_seg_t *tp_unit_last(tp_planner_t *tp, const tp_seg_t *h)
{
    return tp_seg_at(tp, h->unit_last);
}

/* The open unit's provisional body is one element; when it stays (the executor is already on it)
 * give each move its own element over the same stretch, so the executing move is reported right. */
void tp_unit_split_body(tp_planner_t *tp, tp_seg_t *h, uint64_t body_elem)
{
    if (h->unit_last == h->serial || body_elem + 1 != tp->elem_head)
        return;
    tp_elem_t body = *tp_elem_at(tp, body_elem);
    if (body.owner != h->serial || body.is_blend)
        return;
    tp->elem_head = body_elem;
    double u1 = body.u0 + body.len, s = body.s0;
    for (uint64_t k = h->serial; k <= h->unit_last; k++) {
        tp_seg_t *m = tp_seg_at(tp, k);
        double a = fmax(body.u0, m->own0), b = k == h->unit_last ? u1 : fmin(u1, m->own1);
        if (!(b > a))
            continue;
        tp_elem_t *e = tp_elem_at(tp, tp->elem_head);
        e->owner = m->serial;
        e->geo_seg = h->serial;
        e->is_blend = 0;
        e->u0 = a;
        e->s0 = s;
        e->len = b - a;
        s += b - a;
        m->s_end = s;
        tp->elem_head++;
    }
    while (tp->ex.elem > tp->elem_tail && tp->ex.elem >= tp->elem_head)
        tp->ex.elem--;
    tp->ex.elem = tp->ex.elem < body_elem ? tp->ex.elem : body_elem;
    tp_exec_locate(tp);
}
