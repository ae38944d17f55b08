/* tp_queue.c: adding moves: geometry, junction choice, blend sizing and the one-move-delayed emission. */
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
#define TP_BLEND_TRIES 5

/* Segments added and not yet completed. */
int tp_queue_live(const tp_planner_t *tp)
{
    return (int)(tp->seg_head - tp->seg_done);
}

/* Forget everything queued; the position stays. */
void tp_queue_reset(tp_planner_t *tp)
{
    tp->seg_head = tp->seg_tail = tp->seg_done = 0;
    tp->elem_head = tp->elem_tail = 0;
    tp->reg_head = tp->reg_tail = 0;
    tp->aout_head = tp->aout_tail = 0;
    tp->reg_open = 0;
    tp->stop_next = 1;
    tp->prov.valid = 0;
    tp->prev.valid = 0;
    tp->path_version++;
    tp->s_emit = 0.0;
    tp->goal = tp->pos;
    memset(&tp->ex, 0, sizeof(tp->ex));
    tp->ex.tap = TP_TAP_NONE;
    tp->ex.unlock_joint = -1;
}

/* Free ring entries the executor no longer needs. */
static void reclaim(tp_planner_t *tp)
{
    while (tp->elem_tail < tp->ex.elem && tp->elem_tail < tp->elem_head)
        tp->elem_tail++;
    while (tp->reg_tail < tp->ex.reg && tp->reg_tail < tp->reg_head)
        tp->reg_tail++;
    uint64_t keep = tp->seg_done;
    if (tp->seg_head >= 2 && keep > tp->seg_head - 2)
        keep = tp->seg_head - 2;        /* the last two moves hold the pending junction */
    if (tp->elem_tail < tp->elem_head) {
        uint64_t g = tp_elem_at(tp, tp->elem_tail)->geo_seg;
        if (g < keep)
            keep = g;
    }
    while (tp->seg_tail < keep)
        tp->seg_tail++;
}

/* Per-axis and path limits of a move. */
static void seg_limits(const tp_planner_t *tp, tp_seg_t *s)
{
    const tp_limits_t *l = &tp->lim;
    int scurve = tp->type == TP_PLANNER_SCURVE;
    memset(&s->lim, 0, sizeof(s->lim));
    for (int i = 0; i < TP_NAX; i++) {
        s->lim.vel[i] = l->axis_vel[i] > 0.0 ? l->axis_vel[i] : 0.0;
        s->lim.acc[i] = l->axis_acc[i] > 0.0 ? l->axis_acc[i] : 0.0;
        s->lim.jerk[i] = scurve && l->axis_jerk[i] > 0.0 ? l->axis_jerk[i] : 0.0;
    }
    double v = s->in.ini_maxvel > 0.0 ? s->in.ini_maxvel : INFINITY;
    int linear = s->geo.metric != TP_METRIC_ABC && s->sync != TP_SYNC_POS;
    if (linear && l->vlimit > 0.0)
        v = fmin(v, l->vlimit);
    s->lim.vel[TP_PATH_AX] = isfinite(v) ? v : 0.0;
    s->lim.acc[TP_PATH_AX] = s->in.acc > 0.0 ? s->in.acc : (l->amax > 0.0 ? l->amax : 1.0);
    double j = s->in.jerk > 0.0 ? s->in.jerk : l->jmax;
    s->lim.jerk[TP_PATH_AX] = scurve && j > 0.0 ? j : 0.0;
}

/* Geometry of a new move from the queue end. */
static int seg_geometry(tp_planner_t *tp, tp_seg_t *s)
{
    tp_vec_t end = tp_vec_from_pose(&s->in.end);
    if (!tp_vec_finite(&end))
        return -2;
    if (s->in.kind == TP_SEG_CIRCLE) {
        double c[3] = {s->in.center.x, s->in.center.y, s->in.center.z};
        double n[3] = {s->in.normal.x, s->in.normal.y, s->in.normal.z};
        if (!isfinite(c[0] + c[1] + c[2] + n[0] + n[1] + n[2]))
            return -2;
        return tp_geo_arc(&s->geo, &tp->goal, &end, c, n, s->in.turn);
    }
    return tp_geo_line(&s->geo, &tp->goal, &end);
}

/* Numbers a move carries are usable. */
static int seg_valid(const tp_segment_t *in)
{
    if (!isfinite(in->vel) || !isfinite(in->ini_maxvel) || !isfinite(in->acc) ||
        !isfinite(in->jerk) || !isfinite(in->tap_uu_per_rev))
        return 0;
    if (in->vel < 0.0 || in->ini_maxvel < 0.0 || in->acc < 0.0 || in->jerk < 0.0)
        return 0;
    if ((int)in->kind < TP_SEG_LINE || (int)in->kind > TP_SEG_RIGID_TAP)
        return 0;
    return (int)in->motion_type >= TP_MOTION_IDLE && (int)in->motion_type <= TP_MOTION_INDEXROTARY;
}

/* How the previous move meets the new one. */
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
    int cond = (int)a->term;
    tp_corner_describe(c, &a->geo, &b->geo);
    if (cond == TP_TERM_COND_STOP || c->theta > TP_REVERSAL_RAD)
        return TP_JCT_STOP;
    int smooth = c->kink <= TP_KINK_SMOOTH || tp->type != TP_PLANNER_SCURVE;
    if (c->theta < TP_TANGENT_RAD && (smooth || cond != TP_TERM_COND_BLEND))
        return TP_JCT_TANGENT;
    if (cond != TP_TERM_COND_BLEND || a->sync == TP_SYNC_POS)
        return c->theta < TP_TANGENT_RAD ? TP_JCT_TANGENT : TP_JCT_STOP;
    return TP_JCT_BLEND;
}

/* Cut lengths the blend between a and b wants, before the length limits. */
static double blend_want(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b, const tp_corner_t *c)
{
    double v_need = fmin(a->in.vel, b->in.vel) * fmax(1.0, tp->lim.max_feed_override);
    if (a->in.motion_type == TP_MOTION_TRAVERSE || b->in.motion_type == TP_MOTION_TRAVERSE)
        v_need = fmax(v_need, fmin(a->in.ini_maxvel, b->in.ini_maxvel));
    double acc = fmin(a->lim.acc[TP_PATH_AX], b->lim.acc[TP_PATH_AX]);
    double jerk = tp->type == TP_PLANNER_SCURVE ? fmin(a->lim.jerk[TP_PATH_AX], b->lim.jerk[TP_PATH_AX]) : 0.0;
    for (int i = 0; i < TP_NAX; i++) {
        if (a->lim.acc[i] > 0.0)
            acc = fmin(acc, a->lim.acc[i]);
        if (jerk > 0.0 && a->lim.jerk[i] > 0.0)
            jerk = fmin(jerk, a->lim.jerk[i]);
    }
    double d = 1.5 * tp_blend_need_cut(c, v_need, 0.7 * acc, jerk > 0.0 ? 0.4 * jerk : 0.0);
    return d;
}

/* Store the cuts of a new blend between a (final except its end) and b (just added). */
static void plan_cuts(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b, const tp_corner_t *c, double tol)
{
    double d = blend_want(tp, a, b, c);
    if (tol > 0.0)
        d = fmin(d, tp_blend_tol_cut(c, TP_TOL_SHARE * tol));
    a->cut_out = fmin(d, fmin(0.5 * a->geo.len, a->geo.len - a->cut_in));
    b->cut_in = fmin(d, 0.5 * b->geo.len);
}

/* Build the blend a -> b with its planned cuts, shrinking until it keeps the tolerance. */
static int build_blend(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b, double tol, double *shrunk_a)
{
    tp_corner_t c;
    tp_blend_spec_t spec;
    tp_corner_describe(&c, &a->geo, &b->geo);
    memset(&spec, 0, sizeof(spec));
    spec.da = a->cut_out;
    spec.db = b->cut_in;
    for (int k = 0; k < TP_BLEND_TRIES; k++) {
        double miss, dev;
        if (tp_blend_build(&a->blend, &c, &spec) < 0)
            return -1;
        if (!(tol > 0.0))
            break;
        tp_blend_deviation(&a->blend, &c, &spec, &miss, &dev);
        double worst = fmax(miss, dev);
        if (worst <= tol)
            break;
        if (k == TP_BLEND_TRIES - 1)
            return -1;
        double f = fmin(0.9, TP_TOL_SHARE * tol / worst);
        spec.da *= f;
        spec.db *= f;
    }
    *shrunk_a = a->cut_out - spec.da;
    a->cut_out = spec.da;
    b->cut_in = spec.db;
    (void)tp;
    return 0;
}

/* The executor could still stop before global position s_at. */
static int can_stop_before(const tp_planner_t *tp, double s_at)
{
    const tp_region_t *r = tp->ex.reg < tp->reg_head ? tp_reg_at((tp_planner_t *)tp, tp->ex.reg) : NULL;
    tp_lim1_t lim = {r ? r->a : tp->lim.amax, r ? r->j : 0.0};
    if (!(lim.acc > 0.0))
        lim.acc = 1.0;
    double reach = tp_stop_dist(tp->ex.v, tp->ex.a, &lim);
    return tp->ex.s + reach + tp->ex.v * tp->lim.cycle_time <= s_at;
}

/* Settle the end of a (whose body is already emitted to its end): shorten it and emit the blend a -> b. */
static void emit_junction(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b)
{
    double shrunk = 0.0;
    if (a->jct_out == TP_JCT_BLEND) {
        double blend_start = tp->s_emit - a->cut_out;
        if (!can_stop_before(tp, blend_start) || build_blend(tp, a, b, a->tol, &shrunk) < 0 ||
            tp_emit_truncate(tp, a->cut_out) < 0) {
            a->jct_out = TP_JCT_STOP;
            a->cut_out = 0.0;
            b->cut_in = 0.0;
        }
    }
    tp->prov.valid = 0;
    b->jct_in = a->jct_out;
    a->finalized = 1;
    if (a->jct_out == TP_JCT_BLEND)
        tp_emit_blend(tp, a, b, 0);
    else if (a->jct_out == TP_JCT_STOP)
        tp->stop_next = 1;
    (void)shrunk;
}

/* Fill a new segment record from the add arguments and the sticky state. */
static int seg_fill(tp_planner_t *tp, tp_seg_t *s, const tp_segment_t *in)
{
    memset(s, 0, sizeof(*s));
    s->in = *in;
    s->serial = tp->seg_head;
    s->sync = tp->sync_mode;
    s->sync_k = tp->sync_k;
    s->spindle = tp->sync_spindle;
    if (in->kind == TP_SEG_RIGID_TAP) {
        s->sync = TP_SYNC_POS;
        s->sync_k = in->tap_uu_per_rev;
    }
    int g = seg_geometry(tp, s);
    if (g < 0)
        return g;
    seg_limits(tp, s);
    s->jct_in = TP_JCT_STOP;
    s->jct_out = TP_JCT_OPEN;
    s->term = tp->term_cond;
    s->tol = tp->tolerance;
    return 0;
}

/* Attach the pending synced outputs to a new segment. */
static void take_io(tp_planner_t *tp, tp_seg_t *s)
{
    s->dout_mask = tp->io.dout_mask;
    s->dout_vals = tp->io.dout_vals;
    s->aout_mask = tp->io.aout_mask;
    s->aout_first = (uint32_t)tp->aout_head;
    for (int i = 0; i < TP_MAX_AIO; i++) {
        if (!(tp->io.aout_mask & (1ull << i)))
            continue;
        uint32_t slot = TP_SLOT(tp->aout_head, tp->aout_cap);
        tp->aouts[slot].idx = i;
        tp->aouts[slot].val = tp->io.aout_vals[i];
        tp->aout_head++;
        s->aout_count++;
    }
    tp->io.dout_mask = tp->io.aout_mask = 0;
}

/* Room for one more move in every ring. */
static int have_room(tp_planner_t *tp)
{
    reclaim(tp);
    if (tp_queue_live(tp) >= tp->queue_size)
        return 0;
    if (tp->seg_head - tp->seg_tail + 2 > tp->seg_cap)
        return 0;
    if (tp->aout_head - tp->aout_tail + TP_MAX_AIO > tp->aout_cap)
        return 0;
    return tp_emit_space(tp);
}

/* Add a move: validate, build its geometry, settle the previous junction, emit what is final. */
tp_result_t tp_queue_add(tp_planner_t *tp, const tp_segment_t *in)
{
    if (!in || !seg_valid(in))
        return TP_INVALID_PARAMS;
    if (tp->aborting)
        return TP_BAD_STATE;
    if (!have_room(tp))
        return TP_QUEUE_FULL;
    tp_seg_t *s = tp_seg_at(tp, tp->seg_head);
    int g = seg_fill(tp, s, in);
    if (g == -2)
        return TP_INVALID_PARAMS;
    if (g < 0)
        return in->kind == TP_SEG_CIRCLE ? TP_INVALID_PARAMS : TP_ZERO_LENGTH;
    take_io(tp, s);
    tp_seg_t *last = tp->seg_head > tp->seg_tail ? tp_seg_at(tp, tp->seg_head - 1) : NULL;
    if (last && last->finalized)
        last = NULL;
    if (last && last->serial >= tp->seg_done) {
        tp_corner_t c;
        last->jct_out = classify(tp, last, s, &c);
        if (last->jct_out == TP_JCT_BLEND)
            plan_cuts(tp, last, s, &c, last->tol);
        emit_junction(tp, last, s);
    } else {
        if (last) {
            last->jct_out = TP_JCT_STOP;        /* already run to its end */
            last->finalized = 1;
        }
        tp->prov.valid = 0;
        tp->stop_next = 1;
    }
    tp->seg_head++;
    if (in->kind == TP_SEG_RIGID_TAP) {
        s->jct_out = TP_JCT_STOP;
        s->finalized = 1;
        tp_emit_piece(tp, s, s, 0, 0.0, 0.0, TP_REG_TAP);
        tp->stop_next = 1;
        tp->prov.valid = 0;
        return TP_OK;
    }
    tp->goal = tp_vec_from_pose(&in->end);
    tp_emit_provisional(tp, s);
    return TP_OK;
}
