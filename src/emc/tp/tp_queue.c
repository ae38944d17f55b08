/* tp_queue.c: adding moves: validation, geometry, limits, synced outputs, and the emission order. */
#include <math.h>
#include <string.h>
#include "tp_internal.h"

/* Places of completed moves freed per cycle: at least this many, and a share of those waiting. */
#define TP_RELEASE_MIN 2
#define TP_RELEASE_SPREAD 8

/* Segments added and not yet completed. */
int tp_queue_live(const tp_planner_t *tp)
{
    return (int)(tp->seg_head - tp->seg_done);
}

/* No room for another move: the completed moves free their places gradually (tp_queue_release). */
int tp_queue_full(const tp_planner_t *tp)
{
    return tp->seg_head - tp->seg_room >= (uint64_t)tp->queue_size;
}

/* Once per cycle: free the places of completed moves.  A blend completes all the moves it
 * spans at once; freeing their places over a few cycles spreads the adds that refill them (and
 * their blend construction) instead of taking them all in one cycle.  A queue less than half
 * full gets every place back at once. */
void tp_queue_release(tp_planner_t *tp)
{
    uint64_t lag = tp->seg_done - tp->seg_room;
    if (tp->seg_done < tp->seg_room || 2 * (tp->seg_head - tp->seg_done) < (uint64_t)tp->queue_size) {
        tp->seg_room = tp->seg_done;
        return;
    }
    uint64_t step = (lag + TP_RELEASE_SPREAD - 1) / TP_RELEASE_SPREAD;
    tp->seg_room += lag < TP_RELEASE_MIN ? lag : step < TP_RELEASE_MIN ? TP_RELEASE_MIN : step;
}

/* Forget everything queued; the position stays. */
void tp_queue_reset(tp_planner_t *tp)
{
    tp->seg_head = tp->seg_tail = tp->seg_done = tp->seg_room = 0;
    tp->elem_head = tp->elem_tail = 0;
    tp->reg_head = tp->reg_tail = 0;
    tp->aout_head = tp->aout_tail = 0;
    tp->reg_open = 0;
    tp->stop_next = 1;
    tp->prov.valid = 0;
    tp->prov.lazy = 0;
    tp->prev.valid = 0;
    tp->path_version++;
    tp->s_emit = 0.0;
    tp->goal = tp->pos;
    memset(&tp->ex, 0, sizeof(tp->ex));
    tp->ex.dir = 1;
    tp->ex.tap = TP_TAP_NONE;
    tp->ex.unlock_joint = -1;
}

/* Free ring entries behind the executor, oldest first, only as far as room is needed: what stays
 * is the history reverse run can go back along. */
static void reclaim(tp_planner_t *tp)
{
    uint32_t keep_free = 2 * TP_EMIT_SPACE;
    while (tp->elem_tail < tp->ex.elem && tp->elem_head - tp->elem_tail + keep_free > tp->elem_cap)
        tp->elem_tail++;
    while (tp->reg_tail < tp->ex.reg && tp->reg_head - tp->reg_tail + keep_free > tp->reg_cap)
        tp->reg_tail++;
    uint64_t keep = tp->seg_done;
    if (tp->seg_head > tp->seg_tail) {
        /* the open unit and the one before it hold the pending junction */
        uint64_t h = tp_seg_at(tp, tp->seg_head - 1)->unit;
        if (h > tp->seg_tail)
            h = tp_seg_at(tp, h - 1)->unit;
        if (h < keep)
            keep = h;
    }
    if (tp->elem_tail < tp->elem_head) {
        uint64_t g = tp_elem_at(tp, tp->elem_tail)->geo_seg;
        if (g < keep)
            keep = g;
    }
    while (tp->seg_tail < keep && tp->seg_head - tp->seg_tail + 4 > tp->seg_cap)
        tp->seg_tail++;
    if (tp->seg_head - tp->seg_tail + 4 > tp->seg_cap) {
        /* the history holds the segments: give up elements and regions to free some */
        while (tp->elem_tail < tp->ex.elem && tp_elem_at(tp, tp->elem_tail)->geo_seg < tp->seg_done)
            tp->elem_tail++;
        while (tp->reg_tail < tp->ex.reg && tp_reg_at(tp, tp->reg_tail)->seg < tp->seg_done)
            tp->reg_tail++;
        keep = tp->elem_tail < tp->elem_head ? tp_elem_at(tp, tp->elem_tail)->geo_seg : tp->seg_done;
        if (keep > tp->seg_done)
            keep = tp->seg_done;
        while (tp->seg_tail < keep && tp->seg_tail + 2 < tp->seg_head)
            tp->seg_tail++;
    }
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

/* The unit still open at the queue end (its head), or NULL. */
static tp_seg_t *open_unit(tp_planner_t *tp)
{
    if (tp->seg_head <= tp->seg_tail)
        return NULL;
    tp_seg_t *last = tp_seg_at(tp, tp->seg_head - 1);
    tp_seg_t *h = tp_unit_head(tp, last);
    if (h->finalized || last->serial < tp->seg_done || h->serial < tp->seg_tail)
        return NULL;
    return h;
}

/* Head of the unit before unit h, when the blend into h comes from it. */
static tp_seg_t *unit_before(tp_planner_t *tp, tp_seg_t *h)
{
    if (h->jct_in != TP_JCT_BLEND || h->serial <= tp->seg_tail)
        return NULL;
    return tp_unit_head(tp, tp_seg_at(tp, h->serial - 1));
}

/* Fill a new segment record from the add arguments and the sticky state. */
static int seg_fill(tp_planner_t *tp, tp_seg_t *s, const tp_segment_t *in)
{
    memset(s, 0, sizeof(*s));
    s->in = *in;
    s->serial = tp->seg_head;
    s->unit = s->unit_last = s->serial;
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
    s->own0 = 0.0;
    s->own1 = s->geo.len;
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
    if (tp_queue_full(tp))
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
    tp_seg_t *last = open_unit(tp);
    int rollback_ok = last && tp->prov.valid && tp_jct_can_stop_before(tp, tp->prov.s_emit);
    if (rollback_ok && tp_unit_can_absorb(tp, last, s)) {
        /* the new move extends the open unit: emit that unit again, longer */
        tp_emit_rollback(tp);
        tp_unit_absorb(tp, last, s);
        tp->seg_head++;
        tp->goal = tp_vec_from_pose(&in->end);
        tp_jct_provisional(tp, unit_before(tp, last), last);
        return TP_OK;
    }
    if (last)
        tp_jct_plan(tp, last, s);
    if (rollback_ok) {
        tp_emit_rollback(tp);
        tp_jct_commit(tp, unit_before(tp, last), last, s);
    } else {
        if (last) {
            tp_jct_provisional_due(tp, 1);            /* the tail stays: it must exist */
            last->jct_out = s->jct_in = TP_JCT_STOP;  /* already on its way to its end */
            if (tp->prov.valid)
                tp_unit_split_body(tp, last, tp->prov.body_elem);
            for (uint64_t k = last->serial; k <= last->unit_last; k++)
                tp_seg_at(tp, k)->finalized = 1;
        }
        tp->prov.valid = 0;
        tp->stop_next = 1;
        last = NULL;
    }
    tp->seg_head++;
    if (in->kind == TP_SEG_RIGID_TAP) {
        s->jct_in = TP_JCT_STOP;
        s->jct_out = TP_JCT_STOP;
        tp->stop_next = 1;
        tp_jct_commit(tp, NULL, s, NULL);
        tp->prov.valid = 0;
        return TP_OK;
    }
    tp->goal = tp_vec_from_pose(&in->end);
    tp_jct_provisional(tp, last, s);
    return TP_OK;
}
