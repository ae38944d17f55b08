/* tp_planner.c: life cycle, configuration, queue control and queries of a planner. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tp_internal.h"
#include "tp_planner.h"

/* Largest queue a planner accepts (moves). */
#define TP_QUEUE_MAX 1000000
/* Ring sizes per queued move: elements and regions per move, synced analog outputs per move. */
#define TP_ELEMS_PER_SEG (4 + TP_BLEND_PIECES)
#define TP_AOUTS_PER_SEG 4

/* Touch every page of a block so that the servo cycle never takes a page fault on it. */
static void prefault(void *mem, size_t bytes)
{
    volatile unsigned char *p = mem;
    for (size_t k = 0; k < bytes; k += 4096)
        p[k] = 0;
    if (bytes)
        p[bytes - 1] = 0;
}

/* Allocate the rings, fill defaults; NULL on a bad size or no memory. */
tp_planner_t *tp_planner_create(int queue_size)
{
    if (queue_size < 1 || queue_size > TP_QUEUE_MAX)
        return NULL;
    tp_blend_init();
    tp_planner_t *tp = calloc(1, sizeof(*tp));
    if (!tp)
        return NULL;
    tp->queue_size = queue_size;
    tp->seg_cap = 2 * (uint32_t)queue_size + 8;   /* as many again for reverse-run history */
    tp->elem_cap = tp->reg_cap = TP_ELEMS_PER_SEG * tp->seg_cap + 4 * TP_EMIT_SPACE;
    tp->aout_cap = TP_AOUTS_PER_SEG * tp->seg_cap + TP_MAX_AIO;
    tp->segs = calloc(tp->seg_cap, sizeof(*tp->segs));
    tp->elems = calloc(tp->elem_cap, sizeof(*tp->elems));
    tp->regs = calloc(tp->reg_cap, sizeof(*tp->regs));
    tp->aouts = calloc(tp->aout_cap, sizeof(*tp->aouts));
    if (!tp->segs || !tp->elems || !tp->regs || !tp->aouts) {
        tp_planner_destroy(tp);
        return NULL;
    }
    prefault(tp->segs, tp->seg_cap * sizeof(*tp->segs));
    prefault(tp->elems, tp->elem_cap * sizeof(*tp->elems));
    prefault(tp->regs, tp->reg_cap * sizeof(*tp->regs));
    prefault(tp->aouts, tp->aout_cap * sizeof(*tp->aouts));
    tp->lim.cycle_time = 0.001;
    tp->lim.amax = 1.0;
    tp->lim.max_feed_override = 1.0;
    tp->term_cond = TP_TERM_COND_BLEND;
    tp->type = TP_PLANNER_TRAPEZOID;
    tp->type_pending = -1;
    tp_queue_reset(tp);
    return tp;
}

/* Free a planner (NULL is fine). */
void tp_planner_destroy(tp_planner_t *tp)
{
    if (!tp)
        return;
    free(tp->segs);
    free(tp->elems);
    free(tp->regs);
    free(tp->aouts);
    free(tp);
}

/* Every number finite and not negative. */
static int nonneg(const double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(v[k]) || v[k] < 0.0)
            return 0;
    return 1;
}

/* A jerk limit the S-curve planner can use is configured. */
static int jerk_usable(const tp_limits_t *l)
{
    if (l->jmax > 0.0)
        return 1;
    for (int i = 0; i < TP_NUM_AXES; i++)
        if (l->axis_jerk[i] > 0.0)
            return 1;
    return 0;
}

/* Machine limits and settings (taken by moves added from now on). */
tp_result_t tp_planner_set_limits(tp_planner_t *tp, const tp_limits_t *l)
{
    double scal[] = {l->cycle_time, l->vmax, l->ini_maxvel, l->vlimit, l->amax, l->jmax,
                     l->max_feed_override, l->scurve_peak_scale, l->arc_blend_gap_cycles,
                     l->arc_blend_ramp_freq, l->arc_blend_tangent_kink_ratio};
    if (!tp || !l || !nonneg(scal, (int)(sizeof(scal) / sizeof(scal[0]))) || !(l->cycle_time > 0.0))
        return TP_INVALID_PARAMS;
    if (!nonneg(l->axis_vel, TP_NUM_AXES) || !nonneg(l->axis_acc, TP_NUM_AXES) ||
        !nonneg(l->axis_jerk, TP_NUM_AXES))
        return TP_INVALID_PARAMS;
    tp->lim = *l;
    if (tp->type == TP_PLANNER_SCURVE && !jerk_usable(l))
        tp->type = TP_PLANNER_TRAPEZOID;
    return TP_OK;
}

/* Term condition for the moves added next (G61.1 / G61 / G64 P). */
tp_result_t tp_planner_set_term_cond(tp_planner_t *tp, tp_term_cond_t cond, double tolerance)
{
    if (!tp || (int)cond < TP_TERM_COND_STOP || (int)cond > TP_TERM_COND_BLEND ||
        !isfinite(tolerance) || tolerance < 0.0)
        return TP_INVALID_PARAMS;
    tp->term_cond = cond;
    tp->tolerance = tolerance;
    return TP_OK;
}

/* Trapezoid or S-curve; a switch while moves are queued waits until they are done. */
tp_result_t tp_planner_set_type(tp_planner_t *tp, tp_planner_type_t type)
{
    if (!tp || (type != TP_PLANNER_TRAPEZOID && type != TP_PLANNER_SCURVE))
        return TP_INVALID_PARAMS;
    if (type == TP_PLANNER_SCURVE && !jerk_usable(&tp->lim))
        return TP_NO_JERK_LIMIT;
    if (!tp_planner_is_done(tp)) {
        if (type == tp->type) {
            tp->type_pending = -1;
            return TP_OK;
        }
        tp->type_pending = (int)type;
        return TP_DEFERRED;
    }
    tp->type = type;
    tp->type_pending = -1;
    return TP_OK;
}

/* Set the position when nothing is queued. */
tp_result_t tp_planner_set_pos(tp_planner_t *tp, const EmcPose *pos)
{
    if (!tp || !pos)
        return TP_INVALID_PARAMS;
    tp_vec_t p = tp_vec_from_pose(pos);
    if (!tp_vec_finite(&p))
        return TP_INVALID_PARAMS;
    if (!tp_planner_is_done(tp))
        return TP_BAD_STATE;
    tp->pos = p;
    tp_queue_reset(tp);
    return TP_OK;
}

/* Spindle synchronisation of the moves added next (uu_per_rev 0 = none). */
tp_result_t tp_planner_set_spindle_sync(tp_planner_t *tp, int spindle, double uu_per_rev,
                                        int velocity_mode)
{
    if (!tp || spindle < 0 || spindle >= TP_MAX_SPINDLES || !isfinite(uu_per_rev))
        return TP_INVALID_PARAMS;
    tp->sync_spindle = spindle;
    tp->sync_k = uu_per_rev;
    tp->sync_mode = uu_per_rev == 0.0 ? TP_SYNC_NONE : velocity_mode ? TP_SYNC_VEL : TP_SYNC_POS;
    return TP_OK;
}

/* Digital output set when the next move starts (M62/M63; one pending value per output). */
tp_result_t tp_planner_set_dout(tp_planner_t *tp, int index, int start_value, int end_value)
{
    (void)end_value;
    if (!tp || index < 0 || index >= TP_MAX_DIO)
        return TP_INVALID_PARAMS;
    uint64_t bit = 1ull << index;
    tp->io.dout_mask |= bit;
    tp->io.dout_vals = start_value ? tp->io.dout_vals | bit : tp->io.dout_vals & ~bit;
    return TP_OK;
}

/* Analog output set when the next move starts (M67). */
tp_result_t tp_planner_set_aout(tp_planner_t *tp, int index, double start_value, double end_value)
{
    (void)end_value;
    if (!tp || index < 0 || index >= TP_MAX_AIO || !isfinite(start_value))
        return TP_INVALID_PARAMS;
    tp->io.aout_mask |= 1ull << index;
    tp->io.aout_vals[index] = start_value;
    return TP_OK;
}

/* Forward or reverse run along the queued path. */
tp_result_t tp_planner_set_run_dir(tp_planner_t *tp, int reverse)
{
    if (!tp)
        return TP_INVALID_PARAMS;
    tp->reverse_req = reverse ? 1 : 0;
    return TP_OK;
}

/* Queue a move. */
tp_result_t tp_planner_add(tp_planner_t *tp, const tp_segment_t *seg)
{
    if (!tp)
        return TP_INVALID_PARAMS;
    return tp_queue_add(tp, seg);
}

/* Drop every queued move; the position stays. */
tp_result_t tp_planner_clear(tp_planner_t *tp)
{
    if (!tp)
        return TP_INVALID_PARAMS;
    tp->paused = tp->aborting = 0;
    tp->io.dout_mask = tp->io.aout_mask = 0;
    tp_queue_reset(tp);
    return TP_OK;
}

/* Stop along the path (position-synced moves finish first). */
tp_result_t tp_planner_pause(tp_planner_t *tp)
{
    if (!tp)
        return TP_INVALID_PARAMS;
    tp->paused = 1;
    return TP_OK;
}

/* Continue after a pause. */
tp_result_t tp_planner_resume(tp_planner_t *tp)
{
    if (!tp)
        return TP_INVALID_PARAMS;
    tp->paused = 0;
    return TP_OK;
}

/* Decelerate to rest, then drop the queue. */
tp_result_t tp_planner_abort(tp_planner_t *tp)
{
    if (!tp)
        return TP_INVALID_PARAMS;
    if (tp_planner_is_done(tp)) {
        tp->paused = 0;
        tp_queue_reset(tp);
        return TP_OK;
    }
    tp->aborting = 1;
    return TP_OK;
}

/* Inputs usable: finite overrides and spindle values. */
static int inputs_valid(const tp_cycle_in_t *in)
{
    if (!isfinite(in->feed_scale) || !isfinite(in->rapid_scale) || !isfinite(in->adaptive_feed))
        return 0;
    for (int k = 0; k < TP_MAX_SPINDLES; k++)
        if (!isfinite(in->spindle[k].revs) || !isfinite(in->spindle[k].speed_rps))
            return 0;
    return 1;
}

/* One servo cycle; a deferred planner type switch lands once the queue is done. */
tp_result_t tp_planner_run_cycle(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out)
{
    if (!tp || !in || !out)
        return TP_INVALID_PARAMS;
    tp_cycle_in_t safe = *in;
    if (!inputs_valid(in)) {
        safe.feed_scale = safe.rapid_scale = 0.0;
        safe.adaptive_feed = 0.0;
        for (int k = 0; k < TP_MAX_SPINDLES; k++) {
            if (!isfinite(safe.spindle[k].revs))
                safe.spindle[k].revs = 0.0;
            if (!isfinite(safe.spindle[k].speed_rps))
                safe.spindle[k].speed_rps = 0.0;
        }
    }
    if (tp->type_pending >= 0 && tp_planner_is_done(tp)) {
        tp->type = (tp_planner_type_t)tp->type_pending;
        tp->type_pending = -1;
    }
    tp_result_t r = tp_cycle_run(tp, &safe, out);
    return r == TP_OK && !inputs_valid(in) ? TP_INVALID_PARAMS : r;
}

/* Nothing queued and at rest. */
int tp_planner_is_done(const tp_planner_t *tp)
{
    return tp && tp_queue_live(tp) == 0 && tp->ex.v <= 0.0 && tp->ex.tap == TP_TAP_NONE;
}

/* Moves queued, the executing ones included. */
int tp_planner_queue_depth(const tp_planner_t *tp)
{
    return tp ? tp_queue_live(tp) : 0;
}

/* No room for another move. */
int tp_planner_queue_full(const tp_planner_t *tp)
{
    return tp ? tp_queue_full(tp) : 1;
}

/* Current commanded position. */
int tp_planner_get_pos(const tp_planner_t *tp, EmcPose *pos)
{
    if (!tp || !pos)
        return -1;
    *pos = tp_vec_to_pose(&tp->pos);
    return 0;
}

/* Planner type in force. */
int tp_planner_type(const tp_planner_t *tp)
{
    return tp ? (int)tp->type : -1;
}

/* Cycles without a safe continuation. */
unsigned long tp_planner_emergencies(const tp_planner_t *tp)
{
    return tp ? (unsigned long)tp->emergencies : 0;
}

const tp_ops_t tp_library_ops = {
    TP_OPS_VERSION, sizeof(tp_ops_t), "tp",
    tp_planner_create, tp_planner_destroy,
    tp_planner_set_limits, tp_planner_set_term_cond, tp_planner_set_type, tp_planner_set_pos,
    tp_planner_set_spindle_sync, tp_planner_set_dout, tp_planner_set_aout, tp_planner_set_run_dir,
    tp_planner_add, tp_planner_clear, tp_planner_pause, tp_planner_resume, tp_planner_abort,
    tp_planner_run_cycle,
    tp_planner_is_done, tp_planner_queue_depth, tp_planner_queue_full, tp_planner_get_pos,
    tp_planner_type,
};
