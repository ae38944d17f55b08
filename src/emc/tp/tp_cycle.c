/* tp_cycle.c: one servo cycle: overrides, waits at segment starts, motion, segment bookkeeping, outputs. */
#include <math.h>
#include <string.h>
#include "tp_internal.h"

/* Segment being executed (the owner of the current element), or NULL. */
static tp_seg_t *current_seg(tp_planner_t *tp)
{
    if (tp->seg_done >= tp->seg_head || tp->ex.elem >= tp->elem_head)
        return NULL;
    return tp_seg_at(tp, tp_elem_at(tp, tp->ex.elem)->owner);
}

/* Net feed and rapid scales from the inputs and the enables queued with the current move. */
static void net_scales(tp_planner_t *tp, const tp_cycle_in_t *in, const tp_seg_t *s, double *fs,
                       double *rs)
{
    uint32_t en = s ? s->in.enables : (TP_ENABLE_FS | TP_ENABLE_FH);
    double mfo = tp->lim.max_feed_override > 0.0 ? tp->lim.max_feed_override : 1.0;
    double f = 1.0, r = 1.0;
    if (en & TP_ENABLE_FS) {
        f = isfinite(in->feed_scale) && in->feed_scale > 0.0 ? in->feed_scale : 0.0;
        r = isfinite(in->rapid_scale) && in->rapid_scale > 0.0 ? in->rapid_scale : 0.0;
    }
    if (en & TP_ENABLE_AF) {
        double af = isfinite(in->adaptive_feed) ? fmin(fabs(in->adaptive_feed), mfo) : 0.0;
        f *= af;
        r *= af;
    }
    int synced = s && s->sync == TP_SYNC_POS;
    if ((en & TP_ENABLE_FH) && in->feed_hold)
        f = r = 0.0;
    if (in->feed_inhibit && !synced)
        f = r = 0.0;
    if ((tp->paused && !synced) || tp->aborting)
        f = r = 0.0;
    *fs = fmin(f, mfo);
    *rs = fmin(r, 1.0);
}

/* Emit the synced outputs of a segment that starts now. */
static void start_segment(tp_planner_t *tp, tp_seg_t *s, tp_cycle_out_t *out)
{
    if (s->started)
        return;
    s->started = 1;
    out->dout_change_mask |= s->dout_mask;
    out->dout_values = (out->dout_values & ~s->dout_mask) | (s->dout_vals & s->dout_mask);
    for (uint32_t k = 0; k < s->aout_count; k++) {
        uint32_t slot = TP_SLOT(s->aout_first + k, tp->aout_cap);
        int idx = tp->aouts[slot].idx;
        out->aout_change_mask |= 1ull << idx;
        out->aout_values[idx] = tp->aouts[slot].val;
    }
    if (s->aout_count)
        tp->aout_tail = s->aout_first + s->aout_count;
}

/* Mark segments before the current one done and start every segment entered this cycle. */
static void track_segments(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out)
{
    uint64_t owner = tp->seg_done;
    if (tp->ex.elem < tp->elem_head)
        owner = tp_elem_at(tp, tp->ex.elem)->owner;
    for (uint64_t k = tp->seg_done; k <= owner && k < tp->seg_head; k++)
        start_segment(tp, tp_seg_at(tp, k), out);
    if (owner > tp->seg_done)
        tp->seg_done = owner;
    const tp_region_t *last = tp->reg_head > 0 ? tp_reg_at(tp, tp->reg_head - 1) : NULL;
    int at_end = last && tp->ex.s >= last->s0 + last->len && tp->ex.v <= 0.0;
    /* a rigid tap is a region of no length: the end is reached only once it has run */
    if (last && (last->flags & TP_REG_TAP) && tp->ex.cleared_stop != tp->reg_head)
        at_end = 0;
    int all_emitted = !(tp->prov.valid && tp->prov.lazy);
    if (at_end && all_emitted && tp->ex.tap == TP_TAP_NONE && !tp->ex.waiting &&
        !tp_sync_end_hold(tp, in))
        tp->seg_done = tp->seg_head;
}

/* Honour a stop at the start of the current region: waits before its segment may move. */
static int hold_at_stop(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out)
{
    if (tp->ex.reg >= tp->reg_head)
        return 0;
    const tp_region_t *r = tp_reg_at(tp, tp->ex.reg);
    if (!(r->flags & (TP_REG_STOP | TP_REG_TAP)) || tp->ex.cleared_stop == tp->ex.reg + 1)
        return 0;
    if (tp->ex.s > r->s0 || tp->ex.v > 0.0)
        return 0;
    tp_seg_t *s = tp_seg_at(tp, r->seg);
    if (tp_sync_start_wait(tp, in, s, out))
        return 1;
    tp->ex.cleared_stop = tp->ex.reg + 1;
    return 0;
}

/* Fill the outputs that describe the executor. */
static void report(tp_planner_t *tp, tp_cycle_out_t *out, double fs, double rs)
{
    tp_seg_t *s = current_seg(tp);
    out->pos = tp_vec_to_pose(&tp->pos);
    out->current_vel = tp->ex.tap != TP_TAP_NONE ? fabs(tp->ex.tap_v) : tp->ex.v;
    out->queue_depth = tp_queue_live(tp);
    out->queue_full = tp_queue_full(tp);
    out->done = out->queue_depth == 0 && tp->ex.v <= 0.0 && tp->ex.dir > 0 && !tp->reverse_req;
    out->paused = tp->paused && tp->ex.v <= 0.0;
    out->reverse = tp->ex.dir < 0;
    out->rigid_tap_state = tp->ex.tap;
    out->unlock_joint = tp->ex.unlock_joint;
    for (int k = 0; k < TP_MAX_SPINDLES; k++)
        out->spindle_reverse[k] = tp->ex.tap >= TP_TAP_REVERSING && tp->ex.tap <= TP_TAP_RETRACTION &&
                                  k == tp->ex.spindle;
    out->spindle_sync_waiting = tp->ex.waiting;
    if (!s)
        return;
    tp_vec_t end = tp_vec_from_pose(&s->in.end);
    tp_vec_t dtg = tp_vec_sub(&end, &tp->pos);
    out->dtg = tp_vec_to_pose(&dtg);
    out->distance_to_go = fmax(0.0, s->s_end - tp->ex.s);
    out->requested_vel = fmin(s->in.vel, s->in.ini_maxvel > 0.0 ? s->in.ini_maxvel : s->in.vel);
    out->net_feed_scale = s->in.motion_type == TP_MOTION_TRAVERSE ? rs : fs;
    out->motion_type = s->in.motion_type;
    out->exec_id = s->in.id;
    out->exec_tag = s->in.tag;
    out->active_depth = tp_elem_at(tp, tp->ex.elem)->is_blend ? 2 : 1;
}

/* One cycle of motion in the executor's direction; a change of direction waits until at rest. */
static void move(tp_planner_t *tp, const tp_cycle_in_t *in, const tp_seg_t *s, double fs, double rs)
{
    tp_window_t w;
    int want = tp_rev_wanted(tp, in, s);
    double sp = tp_sync_spindle_rps(tp, in);
    if (want != tp->ex.dir && tp->ex.v <= 0.0) {
        tp->ex.dir = want;
        tp->ex.a = 0.0;
        tp->ex.window_end = 0.0;
        tp->prev.valid = 0;
    }
    tp_window_build(tp, &w, fs, rs, sp, tp->ex.dir);
    if (want != tp->ex.dir) {
        for (int k = 0; k < w.nr; k++)
            w.r[k].v = 0.0;             /* come to rest before turning round */
    } else if (tp->ex.dir > 0) {
        tp_window_settle(tp, &w, fs, rs, sp);
        tp_sync_adjust(tp, in, &w);
    }
    if (tp->ex.dir > 0) {
        tp_exec_move(tp, &w, tp->lim.cycle_time);
        tp_exec_locate(tp);
        return;
    }
    tp->ex.s = -tp->ex.s;
    tp_exec_move(tp, &w, tp->lim.cycle_time);
    tp->ex.s = -tp->ex.s;
    tp_rev_locate(tp);
}

/* Finish an abort once at rest: drop the queue where the machine stands. */
static void finish_abort(tp_planner_t *tp)
{
    if (!tp->aborting || tp->ex.v > 0.0 || tp->ex.tap != TP_TAP_NONE)
        return;
    tp->aborting = 0;
    tp->paused = 0;
    tp_queue_reset(tp);
}

/* One servo cycle. */
tp_result_t tp_cycle_run(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out)
{
    double fs, rs;
    memset(out, 0, sizeof(*out));
    tp_seg_t *s = current_seg(tp);
    net_scales(tp, in, s, &fs, &rs);
    tp_jct_provisional_due(tp, 0);
    if (tp->reg_head > tp->reg_tail && (tp->seg_done < tp->seg_head || tp->ex.dir < 0 ||
                                        tp_rev_wanted(tp, in, s) < 0)) {
        if (tp->ex.tap != TP_TAP_NONE)
            tp_sync_tap_cycle(tp, in, out);
        else if (tp->ex.dir < 0 || !hold_at_stop(tp, in, out))
            move(tp, in, s, fs, rs);
        track_segments(tp, in, out);
        if (tp->ex.tap == TP_TAP_NONE)
            tp->pos = tp_exec_position(tp);
        else
            tp->pos = tp_sync_tap_position(tp);
    }
    finish_abort(tp);
    tp_queue_release(tp);
    report(tp, out, fs, rs);
    return TP_OK;
}
