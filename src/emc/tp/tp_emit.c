/* tp_emit.c: turn finished geometry into elements and merge their caps into regions. */
#include <math.h>
#include <string.h>
#include "tp_internal.h"

/* Cap steps: caps are rounded down to 1/64 octave so that near-equal pieces share a region. */
#define TP_CAP_STEPS 64.0
/* A region aims at 1/TP_REGION_SHARE of the braking distance at its speed. */
#define TP_REGION_SHARE 24.0
/* Short pieces whose speed caps differ by more than this factor stay apart when the faster one
 * takes more than a cycle at the slower cap, so a short straight between two slow blends can speed
 * up in between (both planners; S-curve contour 0.80 -> 0.77, the other programs unchanged). */
#define TP_REGION_APART 2.0
/* Trapezoid corners whose parabolic blend may keep only a token share for speed changes: turns
 * from 40 degrees (below: sampled curves, whose blends change speed inside) to 160 degrees (above:
 * near reversals, where the blend turns along the lines' own axis and their braking runs on into
 * it), with straight room on each side of at least this many times the blend's cut. */
#define TP_CORNER_TURN_MIN 0.7
#define TP_CORNER_TURN_MAX 2.8
#define TP_CORNER_ROOM_CUTS 4.0
/* Elements a single add may need (blend halves, body, fallback pieces, a unit's moves). */
#define TP_EMIT_PER_ADD TP_EMIT_SPACE

/* Round a positive cap down to the step grid (0 and INFINITY unchanged). */
static double quantize(double x)
{
    if (!(x > 0.0) || !isfinite(x))
        return x;
    return exp2(floor(log2(x) * TP_CAP_STEPS) / TP_CAP_STEPS);
}

/* Speed the planner may ask of a piece of the owner: requested speed times the largest override. */
static double need_speed(const tp_planner_t *tp, const tp_seg_t *s)
{
    double mfo = tp->lim.max_feed_override > 1.0 ? tp->lim.max_feed_override : 1.0;
    if (s->sync != TP_SYNC_NONE || s->in.kind == TP_SEG_RIGID_TAP)
        return s->in.ini_maxvel > 0.0 ? s->in.ini_maxvel : INFINITY;
    if (s->in.motion_type == TP_MOTION_TRAVERSE)
        return s->in.vel > 0.0 ? s->in.vel : s->in.ini_maxvel;
    return s->in.vel * mfo;
}

/* Braking distance estimate of a region at its own caps (for region sizing). */
static double region_reach(const tp_planner_t *tp, const tp_region_t *r)
{
    double v = r->v_mach;
    double fv = fmin(r->v_feed * fmax(1.0, tp->lim.max_feed_override), r->v_rapid);
    if (isfinite(fv))
        v = fmin(v, fv);
    if (!isfinite(v) || !(r->a > 0.0))
        return 0.0;
    double d = v * v / (2.0 * r->a);
    if (r->j > 0.0)
        d += v * r->a / r->j;
    return fmax(d / TP_REGION_SHARE, 4.0 * v * tp->lim.cycle_time);
}

/* The executor is far enough from the open region that lowering its caps is safe. */
static int region_far(const tp_planner_t *tp, const tp_region_t *r)
{
    tp_lim1_t lim = {0.5 * r->a, r->j > 0.0 ? 0.5 * r->j : 0.0};
    if (!(lim.acc > 0.0))
        return 0;
    double stop = tp_stop_dist(tp->ex.v, tp->ex.a, &lim);
    return r->s0 - tp->ex.s > 2.0 * stop + tp->ex.v * 4.0 * tp->lim.cycle_time + 1e-9;
}

/* Merge a piece into the open region, or open a new region. */
static void region_add(tp_planner_t *tp, const tp_region_t *piece)
{
    if (tp->reg_open && tp->reg_head > tp->reg_tail) {
        tp_region_t *r = tp_reg_at(tp, tp->reg_head - 1);
        int same = piece->v_mach == r->v_mach && piece->a == r->a && piece->j == r->j &&
                   piece->a_rest == r->a_rest &&
                   piece->v_feed == r->v_feed && piece->v_rapid == r->v_rapid &&
                   piece->sync_k == r->sync_k;
        int faster = piece->v_mach >= r->v_mach && piece->a >= r->a && piece->j >= r->j &&
                     piece->a_rest >= r->a_rest &&
                     piece->v_feed >= r->v_feed && piece->v_rapid >= r->v_rapid &&
                     piece->sync_k >= r->sync_k;
        int compatible = !(piece->flags & (TP_REG_STOP | TP_REG_TAP)) && piece->flags == r->flags &&
                         !isfinite(piece->v_start) &&
                         fabs(r->s0 + r->len - piece->s0) <= 1e-9 * (1.0 + fabs(piece->s0));
        int short_r = r->len < region_reach(tp, r);
        int short_p = piece->len < region_reach(tp, piece);
        const tp_region_t *fast = piece->v_mach > r->v_mach ? piece : r;
        double slow = fmin(piece->v_mach, r->v_mach);
        int apart = fast->v_mach > TP_REGION_APART * slow &&
                    fast->len > slow * tp->lim.cycle_time;
        if (compatible && (same || (short_r && short_p && !apart && (faster || region_far(tp, r))))) {
            r->v_mach = fmin(r->v_mach, piece->v_mach);
            r->a = fmin(r->a, piece->a);
            r->a_rest = fmin(r->a_rest, piece->a_rest);  /* the smaller chord holds for both */
            r->j = fmin(r->j, piece->j);
            r->v_feed = fmin(r->v_feed, piece->v_feed);
            r->v_rapid = fmin(r->v_rapid, piece->v_rapid);
            r->sync_k = fmin(r->sync_k, piece->sync_k);
            r->len = piece->s0 + piece->len - r->s0;
            return;
        }
    }
    *tp_reg_at(tp, tp->reg_head) = *piece;
    tp->reg_head++;
    tp->reg_open = 1;
}

/* Elementwise smaller of two limit sets (0 = none). */
static void lim_min(tp_axlim_t *out, const tp_axlim_t *a, const tp_axlim_t *b)
{
    for (int i = 0; i < TP_NBOUND; i++) {
        out->vel[i] = a->vel[i] > 0.0 && b->vel[i] > 0.0 ? fmin(a->vel[i], b->vel[i])
                                                           : fmax(a->vel[i], b->vel[i]);
        out->acc[i] = a->acc[i] > 0.0 && b->acc[i] > 0.0 ? fmin(a->acc[i], b->acc[i])
                                                           : fmax(a->acc[i], b->acc[i]);
        out->jerk[i] = a->jerk[i] > 0.0 && b->jerk[i] > 0.0 ? fmin(a->jerk[i], b->jerk[i])
                                                              : fmax(a->jerk[i], b->jerk[i]);
    }
}

/* Region describing a piece: caps from the derivative bounds, feed from the owner; reserve > 0
 * fixes the share kept for speed changes, 0 lets the caps choose it. */
static void piece_region(tp_planner_t *tp, const tp_geo_t *g, double u0, double u1,
                         const tp_axlim_t *lim, const tp_seg_t *owner, uint32_t flags,
                         double reserve, tp_region_t *r)
{
    tp_bounds_t b;
    tp_caps_t c;
    tp_geo_bounds(g, u0, u1, &b);
    /* an arc's body that starts or ends at a stop changes its speed inside it */
    int rest = 0;
    if (g == &owner->geo && g->kind == TP_GEO_ARC)
        rest = (owner->jct_in == TP_JCT_STOP) + (owner->jct_out == TP_JCT_STOP);
    if (reserve > 0.0)
        tp_caps_with_reserve(&b, lim, need_speed(tp, owner), tp->type == TP_PLANNER_SCURVE, reserve, &c);
    if (!(reserve > 0.0) || c.v >= need_speed(tp, owner))
        tp_caps_compute(&b, lim, need_speed(tp, owner), tp->type == TP_PLANNER_SCURVE, u1 - u0, rest, &c);
    if (!isfinite(c.v))
        c.v = 1e9;
    memset(r, 0, sizeof(*r));
    r->s0 = tp->s_emit;
    r->len = u1 - u0;
    double v_need = need_speed(tp, owner);
    /* a straight piece keeps the machine's limits exactly (a lone G0 accelerates at
     * MAX_ACCELERATION and cruises at the speed its axes allow, as in LinuxCNC, however close
     * the requested speed is to it); curved pieces round down to the grid */
    int straight = b.d2[TP_PATH_AX] == 0.0;
    r->v_mach = c.v >= v_need ? v_need : straight ? c.v : quantize(c.v);
    r->a = straight ? c.a : quantize(c.a);
    r->a_rest = fmax(r->a, straight ? c.a_rest : quantize(c.a_rest));
    r->j = straight ? c.j : quantize(c.j);
    r->v_feed = r->v_rapid = INFINITY;
    r->sync_k = INFINITY;
    if (owner->sync == TP_SYNC_POS)
        flags |= TP_REG_SYNC_POS;
    else if (owner->sync == TP_SYNC_VEL) {
        flags |= TP_REG_SYNC_VEL;
        r->sync_k = fabs(owner->sync_k);
    } else {
        /* a blend's parameter is not exactly its length: keep the feed on the path within 1 % */
        double stretch = b.d1[TP_PATH_AX] > 1.01 ? b.d1[TP_PATH_AX] : 1.0;
        if (owner->in.motion_type == TP_MOTION_TRAVERSE)
            r->v_rapid = owner->in.vel > 0.0 ? owner->in.vel / stretch : INFINITY;
        else
            r->v_feed = owner->in.vel / stretch;
    }
    if (owner->in.kind == TP_SEG_RIGID_TAP)
        flags |= TP_REG_TAP;
    r->flags = flags;
    r->v_start = (flags & TP_REG_STOP) ? 0.0 : INFINITY;
    r->seg = owner->serial;
}

/* Append one element [u0, u1] of a geometry with the given limits. */
static void emit_elem(tp_planner_t *tp, tp_seg_t *owner, tp_seg_t *geo_seg, int is_blend,
                      double u0, double u1, const tp_axlim_t *lim, uint32_t flags)
{
    if (!(u1 - u0 > 0.0) && !(flags & TP_REG_TAP))
        return;
    const tp_geo_t *g = is_blend ? &geo_seg->blend : &geo_seg->geo;
    tp_region_t r;
    piece_region(tp, g, u0, u1, lim, owner, flags, 0.0, &r);
    tp_emit_region(tp, owner, geo_seg, is_blend, u0, u1, &r);
}

/* Emit an element [u0, u1] whose caps are already in template r (its position is filled in). */
void tp_emit_region(tp_planner_t *tp, tp_seg_t *owner, tp_seg_t *geo_seg, int is_blend, double u0,
                    double u1, const tp_region_t *tmpl)
{
    tp_region_t r = *tmpl;
    if (!(u1 - u0 > 0.0) && !(r.flags & TP_REG_TAP))
        return;
    if (tp->stop_next) {
        r.flags |= TP_REG_STOP;
        r.v_start = 0.0;
    }
    tp->stop_next = 0;
    r.s0 = tp->s_emit;
    r.len = u1 - u0;
    r.seg = owner->serial;
    tp_elem_t *e = tp_elem_at(tp, tp->elem_head);
    e->owner = owner->serial;
    e->geo_seg = geo_seg->serial;
    e->is_blend = is_blend;
    e->u0 = u0;
    e->s0 = tp->s_emit;
    e->len = u1 - u0;
    tp->elem_head++;
    region_add(tp, &r);
    tp->s_emit += u1 - u0;
    owner->s_end = tp->s_emit;
}

/* Caps of part [u0, u1] of a geometry, as a region template for tp_emit_region. */
void tp_emit_caps(tp_planner_t *tp, tp_seg_t *owner, const tp_geo_t *g, double u0, double u1,
                  const tp_axlim_t *lim, uint32_t flags, tp_region_t *r)
{
    piece_region(tp, g, u0, u1, lim, owner, flags, 0.0, r);
}

/* Emit part [u0, u1] of a segment's own move. */
void tp_emit_piece(tp_planner_t *tp, tp_seg_t *owner, tp_seg_t *geo_seg, int is_blend, double u0,
                   double u1, uint32_t flags)
{
    emit_elem(tp, owner, geo_seg, is_blend, u0, u1, &owner->lim, flags);
}

/* Rough speed through the corner at the far end of a straight part: 0 at a stop, the parabola's
 * with cut `cut` for a blend the tolerance slows down (G1), else the speed wanted. */
static double corner_speed(tp_jct_t j, const tp_want_t *w, double cut, double acc, double v_need)
{
    if (j == TP_JCT_STOP)
        return 0.0;
    if (j != TP_JCT_BLEND || w->shape != TP_BLEND_G1)
        return v_need;
    double s = sin(0.5 * w->theta);
    return s > 0.0 ? fmin(v_need, sqrt(acc * cut / s)) : v_need;
}

/* Share of the acceleration the pieces of the blend a -> b keep for speed changes (0: their caps
 * choose).  A parabolic (trapezoid) blend at a corner between TP_CORNER_TURN_MIN and
 * TP_CORNER_TURN_MAX whose lines leave room on both sides, for the speed change to the
 * neighbouring corner and TP_CORNER_ROOM_CUTS times its cut, changes its speed on those lines:
 * it keeps a token share and turns faster. */
static double blend_reserve(const tp_planner_t *tp, const tp_seg_t *a, const tp_seg_t *b)
{
    const tp_want_t *w = &a->wf_out;
    if (tp->type == TP_PLANNER_SCURVE || w->shape != TP_BLEND_G1 || w->theta < TP_CORNER_TURN_MIN ||
        w->theta > TP_CORNER_TURN_MAX)
        return 0.0;
    double acc = fmin(a->lim.acc[TP_PATH_AX], b->lim.acc[TP_PATH_AX]), v = w->v_need;
    if (!(acc > 0.0) || !isfinite(v))
        return 0.0;
    double v_prev = corner_speed(a->jct_in, &a->wf_in, a->cut_in, acc, v);
    double v_this = corner_speed(TP_JCT_BLEND, w, fmin(a->cut_out, b->cut_in), acc, v);
    double v_next = corner_speed(b->jct_out, &b->wf_out, b->cut_out, acc, v);
    double a_line = a->geo.len - a->cut_in - a->cut_out, b_line = b->geo.len - b->cut_in - b->cut_out;
    int a_room = a_line >= fmax(TP_CORNER_ROOM_CUTS * a->cut_out,
                                fabs(v_this * v_this - v_prev * v_prev) / (2.0 * acc));
    int b_room = b_line >= fmax(TP_CORNER_ROOM_CUTS * b->cut_in,
                                fabs(v_this * v_this - v_next * v_next) / (2.0 * acc));
    return a_room && b_room ? TP_CAPS_RESERVE_CORNER : 0.0;
}

/* Emit the blend stored in a (from a into b): first half owned by a_owner, second by b_owner, each
 * half in TP_BLEND_PIECES / 2 pieces with their own caps (curvature is low near the ends). */
void tp_emit_blend(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *a_owner, tp_seg_t *b, tp_seg_t *b_owner)
{
    tp_axlim_t lim;
    tp_region_t r[TP_BLEND_PIECES];
    double len = a->blend.len, u[TP_BLEND_PIECES + 1], j = INFINITY, reserve = blend_reserve(tp, a, b);
    lim_min(&lim, &a->lim, &b->lim);
    /* the moves' path acceleration and jerk bound speed changes along them; through the corner
     * every axis keeps its own limits, which is what the curve turning between them must obey */
    lim.acc[TP_PATH_AX] = 0.0;
    lim.jerk[TP_PATH_AX] = 0.0;
    for (int k = 0; k <= TP_BLEND_PIECES; k++)
        u[k] = k == TP_BLEND_PIECES ? len : len * k / TP_BLEND_PIECES;
    for (int k = 0; k < TP_BLEND_PIECES; k++) {
        piece_region(tp, &a->blend, u[k], u[k + 1], &lim, 2 * k < TP_BLEND_PIECES ? a_owner : b_owner,
                     0, reserve, &r[k]);
        j = fmin(j, r[k].j);
    }
    /* one jerk for the whole blend: pieces of alternating jerk would let an acceleration started
     * under the larger one run into the smaller one unsettled */
    for (int k = 0; k < TP_BLEND_PIECES; k++) {
        r[k].j = j;
        tp_emit_region(tp, 2 * k < TP_BLEND_PIECES ? a_owner : b_owner, a, 1, u[k], u[k + 1], &r[k]);
    }
}

/* Remember the state before the provisional part. */
void tp_emit_mark(tp_planner_t *tp)
{
    tp->prov.valid = 1;
    tp->prov.lazy = 0;
    tp->prov.elem_head = tp->elem_head;
    tp->prov.reg_head = tp->reg_head;
    if (tp->reg_head > tp->reg_tail)
        tp->prov.last_reg = *tp_reg_at(tp, tp->reg_head - 1);
    tp->prov.reg_open = tp->reg_open;
    tp->prov.stop_next = tp->stop_next;
    tp->prov.s_emit = tp->s_emit;
}

/* Drop the provisional part (the executor has not reached it) so it can be emitted again. */
void tp_emit_rollback(tp_planner_t *tp)
{
    if (!tp->prov.valid)
        return;
    if (tp->prov.lazy) {                /* never emitted: nothing to take back */
        tp->prov.valid = tp->prov.lazy = 0;
        return;
    }
    tp->elem_head = tp->prov.elem_head;
    tp->reg_head = tp->prov.reg_head;
    if (tp->reg_head > tp->reg_tail)
        *tp_reg_at(tp, tp->reg_head - 1) = tp->prov.last_reg;
    tp->reg_open = tp->prov.reg_open;
    tp->stop_next = tp->prov.stop_next;
    tp->s_emit = tp->prov.s_emit;
    tp->prov.valid = 0;
    tp->path_version++;
}

/* Non-zero when the element and region rings can take another add. */
int tp_emit_space(const tp_planner_t *tp)
{
    return tp->elem_head - tp->elem_tail + TP_EMIT_PER_ADD <= tp->elem_cap &&
           tp->reg_head - tp->reg_tail + TP_EMIT_PER_ADD <= tp->reg_cap;
}
