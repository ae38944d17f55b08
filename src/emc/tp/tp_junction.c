/* tp_junction.c: how consecutive moves meet: stop, tangent or blend; blend sizes, tiling of dense moves, emission. */
#include <math.h>
#include <string.h>
#include "tp_internal.h"

/* Reversals sharper than this stop (LinuxCNC: within 2 degrees of going back). */
#define TP_REVERSAL_RAD (M_PI - 2.0 * M_PI / 180.0)
/* Tangent directions closer than this need no blend. */
#define TP_TANGENT_RAD 1e-6
/* Curvature jump (1/units) below which a tangent join counts as smooth. */
#define TP_KINK_SMOOTH 1e-9
/* Share of the tolerance the blend sizing aims at; the rest covers estimate errors. */
#define TP_TOL_SHARE 0.95
#define TP_BLEND_TRIES 4
/* Turns below this (rad) always blend: the S-curve rule that may stop at a corner leaves them. */
#define TP_TILE_MAX_TURN 0.35
/* Turns above this (rad) are corners: blends on both sides of a move meet without curvature (below
 * it a sampled curve, however coarse: the deviation check still bounds the curvature carried). */
#define TP_TILE_CURVE_TURN 0.7
/* Blends are sized for the wanted speed with this margin (trapezoid, S-curve), using these shares
 * of the limits (the values the bench programs run fastest with). */
#define TP_WANT_MARGIN 2.5
#define TP_WANT_MARGIN_JERK 5.0
#define TP_WANT_ACC_SHARE 0.2
#define TP_WANT_JERK_SHARE 0.1
/* Longest cut on one side of a blend, in cuts of the other side: S-curve, trapezoid (whose
 * lopsided blends cost more than the length they gain). */
#define TP_BLEND_SKEW 1.2
#define TP_BLEND_SKEW_TRAP 1.0
/* Without G64 P a blend misses its corner by at most this share of the shorter adjacent move. */
#define TP_FREE_DEV_SHARE 0.25
/* Share of the limits a blend's speed is estimated with when weighed against a stop (what the caps
 * leave after their reserve for speed changes). */
#define TP_STOP_SHARE 0.75
/* Tangent and curvature components below this: the axis does not move through a corner. */
#define TP_AXIS_STILL 1e-12
/* Bisection steps for the common speed of two blends sharing a short move. */
#define TP_SPLIT_ITER 30

/* How move a meets move b. */
static tp_jct_t classify(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b, tp_corner_t *c)
{
    if (a->in.kind == TP_SEG_RIGID_TAP || b->in.kind == TP_SEG_RIGID_TAP)
        return TP_JCT_STOP;
    if (a->in.indexer_jnum >= 0 || b->in.indexer_jnum >= 0 || b->in.atspeed)
        return TP_JCT_STOP;
    if (a->in.motion_type == TP_MOTION_PROBING || b->in.motion_type == TP_MOTION_PROBING)
        return TP_JCT_STOP;
    if (a->sync != b->sync || a->geo.metric != b->geo.metric)
        return TP_JCT_STOP;
    tp_corner_describe(c, &a->geo, &b->geo);
    if (a->term == TP_TERM_COND_STOP || c->theta > TP_REVERSAL_RAD)
        return TP_JCT_STOP;
    int smooth = c->kink <= TP_KINK_SMOOTH || tp->type != TP_PLANNER_SCURVE;
    if (c->theta < TP_TANGENT_RAD && (smooth || a->term != TP_TERM_COND_BLEND))
        return TP_JCT_TANGENT;
    if (a->term != TP_TERM_COND_BLEND || a->sync == TP_SYNC_POS)
        return c->theta < TP_TANGENT_RAD ? TP_JCT_TANGENT : TP_JCT_STOP;
    return TP_JCT_BLEND;
}

/* Tolerance left to a blend between units a and b after their lines' own deviation.  Without
 * G64 P the geometry bounds it, as in LinuxCNC: a share of the shorter adjacent move; for a blend
 * that carries a sampled curve's curvature (tiling), of the shorter adjacent unit, whose merged
 * line it follows (the chords' share would straighten it at every unit). */
static double blend_tol(tp_planner_t *tp, const tp_seg_t *a, const tp_seg_t *b, int curved)
{
    double dev = fmax(a->unit_dev, b->unit_dev);
    if (a->tol > 0.0)
        return a->tol - dev;
    const tp_seg_t *last = tp_unit_last(tp, a);
    double free = curved ? fmin(a->geo.len, b->geo.len) : fmin(last->own1 - last->own0, b->own1 - b->own0);
    free *= TP_FREE_DEV_SHARE;
    return fmax(free - dev, 0.5 * free);
}

/* Cut a blend described by w wants for speed v through its corner. */
static double want_at(const tp_want_t *w, double v)
{
    tp_corner_t c = {NULL, NULL, w->theta, w->kink, w->shape};
    double margin = w->jerk > 0.0 ? TP_WANT_MARGIN_JERK : TP_WANT_MARGIN;
    return fmin(w->cap, margin * tp_blend_need_cut(&c, v, w->acc, w->jerk));
}

/* Shape of a blend: G2 where jerk is limited or where the tolerance lets a G2 blend pass at the
 * speed wanted; otherwise (trapezoid planning, a corner the tolerance slows down) the parabolic G1
 * blend, which turns with the least acceleration a cut of that size allows. */
static void choose_shape(const tp_planner_t *tp, const tp_corner_t *c, tp_want_t *w, double tol)
{
    if (tp->type == TP_PLANNER_SCURVE || want_at(w, w->v_need) < w->cap)
        return;
    tp_corner_t g1 = *c;
    g1.shape = TP_BLEND_G1;
    w->shape = TP_BLEND_G1;
    w->cap = tp_blend_tol_cut(&g1, TP_TOL_SHARE * tol);
}

/* Symmetric cut a blend between a and b wants: enough for the requested speed, within the tolerance. */
static double blend_want(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b, const tp_corner_t *c, tp_want_t *w)
{
    double v_need = fmin(a->in.vel, b->in.vel) * fmax(1.0, tp->lim.max_feed_override);
    if (a->in.motion_type == TP_MOTION_TRAVERSE || b->in.motion_type == TP_MOTION_TRAVERSE)
        v_need = fmax(v_need, fmin(a->in.ini_maxvel, b->in.ini_maxvel));
    /* no faster than the machine allows along either move (a feed far above it asks no more) */
    const double caps[] = {a->in.ini_maxvel, b->in.ini_maxvel, a->lim.vel[TP_PATH_AX],
                           b->lim.vel[TP_PATH_AX]};
    for (int k = 0; k < 4; k++)
        if (caps[k] > 0.0)
            v_need = fmin(v_need, caps[k]);
    double acc = fmin(a->lim.acc[TP_PATH_AX], b->lim.acc[TP_PATH_AX]);
    double jerk = tp->type == TP_PLANNER_SCURVE ? fmin(a->lim.jerk[TP_PATH_AX], b->lim.jerk[TP_PATH_AX]) : 0.0;
    /* the axes that move through the corner (an axis outside the machine has a token limit) */
    tp_jet_t ja = tp_geo_jet(&a->geo, a->geo.len), jb = tp_geo_jet(&b->geo, 0.0);
    for (int i = 0; i < TP_NAX; i++) {
        if (fabs(ja.d1.x[i]) + fabs(jb.d1.x[i]) + fabs(ja.d2.x[i]) + fabs(jb.d2.x[i]) < TP_AXIS_STILL)
            continue;
        if (a->lim.acc[i] > 0.0)
            acc = fmin(acc, a->lim.acc[i]);
        if (jerk > 0.0 && a->lim.jerk[i] > 0.0)
            jerk = fmin(jerk, a->lim.jerk[i]);
    }
    double tol = blend_tol(tp, a, b, 0);
    w->theta = c->theta;
    w->kink = c->kink;
    w->shape = c->shape;
    w->acc = TP_WANT_ACC_SHARE * acc;
    w->jerk = jerk > 0.0 ? TP_WANT_JERK_SHARE * jerk : 0.0;
    w->cap = tp_blend_tol_cut(c, TP_TOL_SHARE * tol);
    w->v_need = v_need;
    choose_shape(tp, c, w, tol);
    return want_at(w, v_need);
}

/* Time a jerk-limited change of speed by dv takes with path acceleration acc and jerk jerk. */
static double change_time(double dv, double acc, double jerk)
{
    if (dv * jerk <= acc * acc)
        return 2.0 * sqrt(dv / jerk);
    return dv / acc + acc / jerk;
}

/* S-curve: a blend the tolerance keeps small is run slowly over all its length; stopping at the
 * corner (exact, within any tolerance) is then the faster way round.  Compares the time lost to
 * cruising at the speed reachable on the shorter move: slowing to the blend's speed and back plus
 * crossing the blend, against slowing to rest and back. */
static int stop_is_faster(const tp_planner_t *tp, const tp_seg_t *a, const tp_seg_t *b, const tp_want_t *w)
{
    double d = fmin(w->cap, 0.5 * fmin(a->geo.len, b->geo.len));   /* short moves share their length */
    if (tp->type != TP_PLANNER_SCURVE || !(w->jerk > 0.0) || !(w->acc > 0.0) || w->theta < TP_TILE_MAX_TURN ||
        want_at(w, w->v_need) < d)
        return 0;                       /* not held back by the tolerance or short moves */
    double acc = w->acc / TP_WANT_ACC_SHARE, jerk = w->jerk / TP_WANT_JERK_SHARE;
    double reach = 0.5 * fmin(a->geo.len, b->geo.len);
    double v_top = fmin(w->v_need, fmin(cbrt(reach * reach * jerk), sqrt(acc * reach)));
    if (a->in.motion_type != TP_MOTION_TRAVERSE && b->in.motion_type != TP_MOTION_TRAVERSE)
        v_top = fmin(v_top, fmin(a->in.vel, b->in.vel));    /* the feed, not its largest override */
    /* an arc on either side is no faster than its curvature allows */
    tp_jet_t ja = tp_geo_jet(&a->geo, a->geo.len), jb = tp_geo_jet(&b->geo, 0.0);
    double k = fmax(sqrt(tp_vec_dot(&ja.d2, &ja.d2)), sqrt(tp_vec_dot(&jb.d2, &jb.d2)));
    if (k > 0.0)
        v_top = fmin(v_top, fmin(sqrt(acc / k), cbrt(jerk / (k * k))));
    tp_corner_t c = {NULL, NULL, w->theta, w->kink, w->shape};
    double len, v = tp_blend_speed_at_cut(&c, d, TP_STOP_SHARE * acc, TP_STOP_SHARE * jerk, &len);
    v = fmin(v, v_top);
    if (!(v_top > 0.0) || !isfinite(v_top) || !(v > 0.0))
        return 0;
    double lost_blend = change_time(v_top - v, acc, jerk) * (v_top - v) / v_top + len / v - len / v_top;
    return change_time(v_top, acc, jerk) < lost_blend;
}

/* Decide the junction between b (the last move) and c (just added) and what blend it wants. */
void tp_jct_plan(tp_planner_t *tp, tp_seg_t *b, tp_seg_t *c)
{
    tp_corner_t cr;
    b->jct_out = classify(tp, b, c, &cr);
    if (b->jct_out == TP_JCT_BLEND) {
        blend_want(tp, b, c, &cr, &b->wf_out);
        if (stop_is_faster(tp, b, c, &b->wf_out))
            b->jct_out = TP_JCT_STOP;
    }
    c->jct_in = b->jct_out;
    b->want_out = c->want_in = b->jct_out == TP_JCT_BLEND ? blend_want(tp, b, c, &cr, &b->wf_out) : 0.0;
    c->wf_in = b->wf_out;
}

/* Share a move too short for both blends' wants: each gets the cut it wants for a common speed
 * through the two corners (a sharp corner needs more length for the same speed than a gentle one),
 * the speed found by bisection; what the first corner gets at that speed, the second the rest. */
static double balanced_cut_in(const tp_seg_t *b, double L)
{
    double lo = 0.0, hi = fmax(b->wf_in.v_need, b->wf_out.v_need);
    if (!(hi > 0.0) || !isfinite(hi))
        return L * b->want_in / (b->want_in + b->want_out);
    for (int k = 0; k < TP_SPLIT_ITER; k++) {
        double mid = 0.5 * (lo + hi);
        if (want_at(&b->wf_in, mid) + want_at(&b->wf_out, mid) <= L)
            lo = mid;
        else
            hi = mid;
    }
    double din = want_at(&b->wf_in, lo), dout = want_at(&b->wf_out, lo);
    double spare = L - din - dout;      /* what neither needs at that speed: shared as the wants */
    return din + spare * b->want_in / (b->want_in + b->want_out);
}

/* Cut lengths of b from the blends at both its ends; tiled when they consume it all. */
static void split(tp_seg_t *b)
{
    double din = b->jct_in == TP_JCT_BLEND ? b->want_in : 0.0;
    double dout = b->jct_out == TP_JCT_BLEND ? b->want_out : 0.0;
    double L = b->geo.len;
    if (din + dout >= L) {
        b->cut_in = din > 0.0 && dout > 0.0 ? balanced_cut_in(b, L) : L * din / (din + dout);
        b->cut_out = L - b->cut_in;
        b->tiled = din > 0.0 && dout > 0.0;
    } else {
        b->cut_in = din;
        b->cut_out = dout;
        b->tiled = 0;
    }
}

/* Discrete curvature at the vertex between a and b: turn of the direction over the mean length. */
static tp_vec_t vertex_curvature(const tp_seg_t *a, const tp_seg_t *b)
{
    tp_jet_t ja = tp_geo_jet(&a->geo, a->geo.len), jb = tp_geo_jet(&b->geo, 0.0);
    tp_vec_t k = tp_vec_sub(&jb.d1, &ja.d1);
    return tp_vec_scale(&k, 2.0 / (a->geo.len + b->geo.len));
}

/* Curvature where the blends on a tiled line b meet, from the curvatures at its two vertices when
 * both turn the same way (none at an inflection); normal to b. */
static void tile_curvature(tp_seg_t *a, tp_seg_t *b, tp_seg_t *c)
{
    b->k_in_set = b->k_out_set = 0;
    if (!b->tiled || b->geo.kind != TP_GEO_LINE || !a || !c || b->wf_in.shape != TP_BLEND_G2 ||
        b->wf_out.shape != TP_BLEND_G2)
        return;
    const tp_vec_t *u = &b->geo.u.line.dir;
    double uu = tp_vec_dot(u, u);
    tp_corner_t c1, c2;
    tp_corner_describe(&c1, &a->geo, &b->geo);
    tp_corner_describe(&c2, &b->geo, &c->geo);
    if (c1.theta > TP_TILE_CURVE_TURN || c2.theta > TP_TILE_CURVE_TURN)
        return;                         /* corners, not a sampled curve: meet without curvature */
    tp_vec_t k1 = vertex_curvature(a, b), k2 = vertex_curvature(b, c);
    k1 = tp_vec_axpy(&k1, -tp_vec_dot(&k1, u) / uu, u);
    k2 = tp_vec_axpy(&k2, -tp_vec_dot(&k2, u) / uu, u);
    double n1 = sqrt(tp_vec_dot(&k1, &k1)), n2 = sqrt(tp_vec_dot(&k2, &k2));
    double cs = n1 > 0.0 && n2 > 0.0 ? tp_vec_dot(&k1, &k2) / (n1 * n2) : 0.0;
    if (cs <= 0.5)
        return;
    tp_vec_t sum = tp_vec_axpy(&k1, 1.0, &k2);
    double ns = sqrt(tp_vec_dot(&sum, &sum));
    /* the gentler of the two (minmod) keeps a blend inside a G64 P tolerance; without P their
     * harmonic mean, which a curve tightening along the run follows more closely */
    double k = b->tol > 0.0 ? fmin(n1, n2) : 2.0 * n1 * n2 / (n1 + n2);
    b->k_in = tp_vec_scale(&sum, cs * k / ns);
    b->k_out = b->k_in;
    b->k_in_set = b->k_out_set = 1;
}

/* Blend a -> b at their cuts; shrinks b's side (and a's when free) until it keeps the tolerance. */
static int build_blend(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b, int a_free, double *a_shrunk)
{
    tp_corner_t c;
    tp_blend_spec_t spec;
    double tol_plain = blend_tol(tp, a, b, 0), tol_curved = blend_tol(tp, a, b, 1);
    tp_corner_describe(&c, &a->geo, &b->geo);
    c.shape = a->wf_out.shape;
    memset(&spec, 0, sizeof(spec));
    spec.da = a->cut_out;
    spec.db = b->cut_in;
    spec.ka_set = a->k_out_set;
    spec.ka = a->k_out;
    spec.kb_set = b->k_in_set;
    spec.kb = b->k_in;
    /* a lopsided blend turns mostly near its short side and is slow over all its length */
    double skew = tp->type == TP_PLANNER_SCURVE ? TP_BLEND_SKEW : TP_BLEND_SKEW_TRAP;
    if (a_free && !spec.ka_set && spec.da > skew * spec.db)
        spec.da = skew * spec.db;
    if (!spec.kb_set && spec.db > skew * spec.da)
        spec.db = skew * spec.da;
    for (int k = 0; k < TP_BLEND_TRIES; k++) {
        if (tp_blend_build(&a->blend, &c, &spec) < 0)
            return -1;
        double tol = spec.ka_set || spec.kb_set ? tol_curved : tol_plain;
        double worst = tp_blend_worst(&a->blend, &c, &spec, tol);
        if (worst <= tol)
            break;
        if (k == TP_BLEND_TRIES - 1)
            return -1;
        if (spec.kb_set) {
            spec.kb_set = 0;            /* first give up the tiling curvature */
            continue;
        }
        double f = fmin(0.9, TP_TOL_SHARE * tol / worst);
        spec.db *= f;
        if (a_free && !spec.ka_set)
            spec.da *= f;
    }
    *a_shrunk = a->cut_out - spec.da;
    a->cut_out = spec.da;
    if (spec.db < b->cut_in || !spec.kb_set) {
        b->tiled = 0;
        b->k_in_set = b->k_out_set = 0;
    }
    b->cut_in = spec.db;
    return 0;
}

/* The executor could still stop before global position s_at. */
int tp_jct_can_stop_before(const tp_planner_t *tp, double s_at)
{
    const tp_region_t *r = tp->ex.reg < tp->reg_head ? tp_reg_at((tp_planner_t *)tp, tp->ex.reg) : NULL;
    tp_lim1_t lim = {r ? r->a : tp->lim.amax, r ? r->j : 0.0};
    if (!(lim.acc > 0.0))
        lim.acc = 1.0;
    double reach = tp_stop_dist(tp->ex.v, tp->ex.a, &lim);
    return tp->ex.s + reach + tp->ex.v * tp->lim.cycle_time <= s_at;
}

/* The rest of unit a after a blend that failed at its far end: from its cut point to its end,
 * where the executor stops.  When the blend into a carried curvature, its cut point lies on the
 * arc off the line (tp_blend.c): a blend from there back onto the line's end replaces the line. */
static void emit_rest(tp_planner_t *tp, tp_seg_t *a)
{
    if (a->k_out_set && a->geo.kind == TP_GEO_LINE && a->cut_out > 0.0) {
        tp_corner_t c;
        tp_blend_spec_t spec;
        memset(&spec, 0, sizeof(spec));
        c.ga = c.gb = &a->geo;
        c.theta = c.kink = 0.0;
        c.shape = TP_BLEND_G2;
        spec.da = a->cut_out;
        spec.db = a->geo.len;
        spec.ka_set = 1;
        spec.ka = a->k_out;
        if (tp_blend_build(&a->blend, &c, &spec) == 0) {
            tp_emit_blend(tp, a, tp_unit_last(tp, a), a, tp_unit_last(tp, a));
            return;
        }
    }
    tp_unit_emit(tp, a, a->geo.len - a->cut_out, a->geo.len, 0);
}

/* Emit the blend a -> b, or the rest of a and a stop at the corner when no blend fits. */
static void emit_in_blend(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b)
{
    double shrunk = 0.0;
    int a_free = !a->k_out_set;
    if (build_blend(tp, a, b, a_free, &shrunk) < 0) {
        /* the rest of a; a curvature carried into its cut point must come to rest there */
        tp->stop_next = tp->stop_next || a->k_out_set;
        emit_rest(tp, a);
        a->jct_out = b->jct_in = TP_JCT_STOP;
        a->cut_out = b->cut_in = 0.0;
        b->tiled = 0;
        b->k_in_set = b->k_out_set = 0;
        tp->stop_next = 1;
        return;
    }
    if (shrunk > 0.0)
        tp_unit_emit(tp, a, a->geo.len - a->cut_out - shrunk, a->geo.len - a->cut_out, 0);
    tp_emit_blend(tp, a, tp_unit_last(tp, a), b, b);
}

/* Settle b for good now that its successor c is known: its cuts, its tiling curvature, the blend
 * into it, its body.  Everything up to the start of the blend b -> c is then committed. */
void tp_jct_commit(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b, tp_seg_t *c)
{
    if (b->jct_in != TP_JCT_BLEND)
        a = NULL;
    split(b);
    tile_curvature(a, b, c);
    if (a)
        emit_in_blend(tp, a, b);
    if (b->cut_in + b->cut_out < b->geo.len * (1.0 - 1e-12)) {
        b->tiled = 0;
        b->k_in_set = b->k_out_set = 0;
    }
    if (b->in.kind == TP_SEG_RIGID_TAP)
        tp_emit_piece(tp, b, b, 0, 0.0, 0.0, TP_REG_TAP);
    else
        tp_unit_emit(tp, b, b->cut_in, b->geo.len - b->cut_out, 0);
    for (uint64_t k = b->serial; k <= b->unit_last; k++)
        tp_seg_at(tp, k)->finalized = 1;
    if (b->jct_out == TP_JCT_STOP)
        tp->stop_next = 1;
}

/* The executor is far from the end of the emitted path: the provisional tail can wait. */
static int path_end_far(const tp_planner_t *tp)
{
    const tp_region_t *r = tp->ex.reg < tp->reg_head ? tp_reg_at((tp_planner_t *)tp, tp->ex.reg) : NULL;
    tp_lim1_t lim = {r ? r->a : tp->lim.amax, r ? r->j : 0.0};
    if (!r || !(lim.acc > 0.0))
        return 0;
    /* the speed the executor may reach: now, or the cap of where it is */
    double v = fmax(tp->ex.v, fmin(r->v_mach, fmin(r->v_feed, r->v_rapid) * fmax(1.0, tp->lim.max_feed_override)));
    double reach = tp_stop_dist(v, fabs(tp->ex.a), &lim);
    return tp->ex.s + 3.0 * reach + 20.0 * v * tp->lim.cycle_time + 1e-6 < tp->s_emit;
}

/* Emit the provisional tail: the blend b -> c (no curvature at c's side) and c's body to its end. */
static void provisional_emit(tp_planner_t *tp, tp_seg_t *b, tp_seg_t *c)
{
    c->cut_in = 0.0;
    c->k_in_set = 0;
    if (b && b->jct_out == TP_JCT_BLEND) {
        double shrunk = 0.0;
        c->cut_in = fmin(c->want_in, c->geo.len);
        if (build_blend(tp, b, c, 0, &shrunk) == 0) {
            tp_emit_blend(tp, b, tp_unit_last(tp, b), c, c);
        } else {
            tp->stop_next = tp->stop_next || b->k_out_set;
            emit_rest(tp, b);
            c->cut_in = 0.0;
            tp->stop_next = 1;
        }
    }
    /* one element for the whole open unit: it is emitted again (per move) when the unit closes */
    tp->prov.body_elem = tp->elem_head;
    if (c->in.kind != TP_SEG_RIGID_TAP)
        tp_emit_piece(tp, c, c, 0, c->cut_in, c->geo.len, 0);
}

/* What the executor may use before c's successor is known: the blend b -> c and c's body.  The
 * next add rolls it back; while the executor is far from the path end it is not even emitted
 * (tp_jct_provisional_due emits it when the executor comes near). */
void tp_jct_provisional(tp_planner_t *tp, tp_seg_t *b, tp_seg_t *c)
{
    tp_emit_mark(tp);
    tp->prov.lazy_b = b ? b->serial : UINT64_MAX;
    tp->prov.lazy_c = c->serial;
    tp->prov.lazy = path_end_far(tp);
    if (!tp->prov.lazy)
        provisional_emit(tp, b, c);
}

/* Emit a postponed provisional tail once the executor comes near the end of the path (or when
 * the tail must stay for good). */
void tp_jct_provisional_due(tp_planner_t *tp, int now)
{
    if (!tp->prov.valid || !tp->prov.lazy || (!now && path_end_far(tp)))
        return;
    tp->prov.lazy = 0;
    tp_seg_t *b = tp->prov.lazy_b == UINT64_MAX ? NULL : tp_seg_at(tp, tp->prov.lazy_b);
    provisional_emit(tp, b, tp_seg_at(tp, tp->prov.lazy_c));
}
