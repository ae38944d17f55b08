/* tp_sync.c: spindle synchronisation (G33 position, G95 velocity), at-speed and index waits, rigid tap phases, locking indexers. */
#include <math.h>
#include "tp_internal.h"

/* Time constant with which position sync closes its error (s). */
#define TP_SYNC_TAU 0.01

/* Spindle of a segment, clamped to the configured range. */
static int seg_spindle(const tp_cycle_in_t *in, const tp_seg_t *s)
{
    int n = in->num_spindles > 0 ? in->num_spindles : 1;
    int sp = s ? s->spindle : 0;
    return sp >= 0 && sp < n && sp < TP_MAX_SPINDLES ? sp : 0;
}

/* Spindle speed (rev/s) velocity sync follows: that of the executing segment's spindle. */
double tp_sync_spindle_rps(const tp_planner_t *tp, const tp_cycle_in_t *in)
{
    double v = in->spindle[tp->ex.spindle >= 0 && tp->ex.spindle < TP_MAX_SPINDLES ? tp->ex.spindle : 0].speed_rps;
    return isfinite(v) ? v : 0.0;
}

/* Spindle direction: commanded direction, else measured. */
static double spindle_dir(const tp_spindle_in_t *sp)
{
    if (sp->speed_cmd_rps < 0.0)
        return -1.0;
    if (sp->speed_cmd_rps > 0.0)
        return 1.0;
    return sp->speed_rps < 0.0 ? -1.0 : 1.0;
}

/* Index handshake: arm, give the arm a cycle, then wait for the encoder to clear it. */
static int index_wait(tp_planner_t *tp, const tp_cycle_in_t *in, int sp, tp_cycle_out_t *out)
{
    if (tp->ex.sync_active)
        return 0;
    if (tp->ex.index_state == 0) {
        out->arm_index[sp] = 1;
        tp->ex.index_state = 1;
        return 1;
    }
    if (tp->ex.index_state == 1) {
        tp->ex.index_state = 2;
        return 1;
    }
    if (in->spindle[sp].index_enable)
        return 1;
    tp->ex.index_state = 0;
    tp->ex.sync_active = 1;
    tp->ex.sync_revs0 = in->spindle[sp].revs;
    tp->ex.sync_s0 = tp->ex.s;
    tp->ex.sync_dir = spindle_dir(&in->spindle[sp]);
    return 0;
}

/* Start the rigid tap state machine at the tap's start point. */
static void tap_start(tp_planner_t *tp, tp_seg_t *s, const tp_cycle_in_t *in)
{
    tp->ex.tap = TP_TAP_TAPPING;
    tp->ex.tap_x = tp->ex.tap_v = tp->ex.tap_a = 0.0;
    tp->ex.tap_seg = s->serial;
    tp->ex.tap_revs_prev = in->spindle[tp->ex.spindle].revs;
}

/* Waits before segment s may start from rest; 1 while waiting (or when a tap took over). */
int tp_sync_start_wait(tp_planner_t *tp, const tp_cycle_in_t *in, tp_seg_t *s, tp_cycle_out_t *out)
{
    int sp = seg_spindle(in, s);
    tp->ex.spindle = sp;
    tp->ex.waiting = 0;
    if (tp->ex.unlock_joint >= 0 && tp->ex.unlock_joint != s->in.indexer_jnum) {
        tp->ex.unlock_joint = -1;       /* relock the indexer of the previous move first */
        tp->ex.relock_pending = 1;
    }
    if (tp->ex.relock_pending) {
        if (in->indexer_unlocked)
            return 1;
        tp->ex.relock_pending = 0;
    }
    if (s->in.indexer_jnum >= 0) {
        tp->ex.unlock_joint = s->in.indexer_jnum;
        if (!in->indexer_unlocked)
            return 1;
    }
    if (s->in.atspeed && !in->spindle[sp].at_speed) {
        tp->ex.waiting = 1;
        return 1;
    }
    if (s->sync != TP_SYNC_POS)
        tp->ex.sync_active = 0;
    else if (index_wait(tp, in, sp, out)) {
        tp->ex.waiting = 1;
        return 1;
    }
    if (s->in.kind == TP_SEG_RIGID_TAP && tp->ex.tap == TP_TAP_NONE) {
        tap_start(tp, s, in);
        return 1;
    }
    return 0;
}

/* Position sync: the speed that keeps the path on the spindle, as the cap of this cycle. */
void tp_sync_adjust(tp_planner_t *tp, const tp_cycle_in_t *in, tp_window_t *w)
{
    const tp_region_t *r = tp_reg_at(tp, tp->ex.reg);
    if (!(r->flags & TP_REG_SYNC_POS)) {
        tp->ex.sync_active = 0;
        return;
    }
    if (!tp->ex.sync_active)
        return;
    tp_seg_t *s = tp_seg_at(tp, r->seg);
    const tp_spindle_in_t *sp = &in->spindle[tp->ex.spindle];
    double k = fabs(s->sync_k);
    /* the position commanded at the end of this cycle should match the spindle read now */
    double target = tp->ex.sync_s0 + (sp->revs - tp->ex.sync_revs0) * tp->ex.sync_dir * k;
    double vel = sp->speed_rps * tp->ex.sync_dir * k;
    double ahead = tp->ex.s + tp->ex.v * tp->lim.cycle_time;
    double v = vel + (target - ahead) / TP_SYNC_TAU;
    for (int k = 0; k < w->nr; k++)
        w->r[k].v = fmin(w->r[k].v, v > 0.0 ? v : 0.0);
}

/* Speed the tap line should have to follow the spindle. */
static double tap_follow(tp_planner_t *tp, const tp_cycle_in_t *in, const tp_seg_t *s)
{
    const tp_spindle_in_t *sp = &in->spindle[tp->ex.spindle];
    double k = fabs(s->sync_k);
    double target = (sp->revs - tp->ex.sync_revs0) * tp->ex.sync_dir * k;
    double ahead = tp->ex.tap_x + tp->ex.tap_v * tp->lim.cycle_time;
    return sp->speed_rps * tp->ex.sync_dir * k + (target - ahead) / TP_SYNC_TAU;
}

/* Move the tap coordinate towards speed vt for one cycle within the tap line's limits. */
static void tap_move(tp_planner_t *tp, const tp_seg_t *s, double vt)
{
    tp_lim1_t lim = {s->lim.acc[TP_PATH_AX], s->lim.jerk[TP_PATH_AX]};
    double vmax = s->lim.vel[TP_PATH_AX] > 0.0 ? s->lim.vel[TP_PATH_AX] : INFINITY;
    vt = fmax(-vmax, fmin(vmax, vt));
    tp_prof_t p;
    tp_prof_velocity(&p, tp->ex.tap_v, tp->ex.tap_a, vt, &lim);
    tp_state1_t st = tp_prof_at(&p, tp->lim.cycle_time);
    tp->ex.tap_x += st.s;
    tp->ex.tap_v = st.v;
    tp->ex.tap_a = st.a;
}

/* Final placement: back to the tap start without sync; 1 when there. */
static int tap_place(tp_planner_t *tp, const tp_seg_t *s)
{
    tp_lim1_t lim = {s->lim.acc[TP_PATH_AX], s->lim.jerk[TP_PATH_AX]};
    double x = tp->ex.tap_x, d = fabs(x);
    if (d <= 1e-9 && fabs(tp->ex.tap_v) <= 1e-6) {
        tp->ex.tap_x = tp->ex.tap_v = tp->ex.tap_a = 0.0;
        return 1;
    }
    double vmax = s->lim.vel[TP_PATH_AX] > 0.0 ? s->lim.vel[TP_PATH_AX] : s->in.ini_maxvel;
    double v = fmin(vmax, tp_chain_vmax(0.0, fmax(0.0, d - 1e-9), &lim));
    tap_move(tp, s, x > 0.0 ? -v : v);
    if ((x > 0.0) != (tp->ex.tap_x > 0.0)) {
        tp->ex.tap_x = tp->ex.tap_v = tp->ex.tap_a = 0.0;
        return 1;
    }
    return 0;
}

/* One cycle of rigid tapping: follow the spindle in and out, then place at the start. */
void tp_sync_tap_cycle(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out)
{
    tp_seg_t *s = tp_seg_at(tp, tp->ex.tap_seg);
    double revs = in->spindle[tp->ex.spindle].revs;
    double turning = (revs - tp->ex.tap_revs_prev) * tp->ex.sync_dir;
    (void)out;
    if (tp->ex.tap == TP_TAP_FINAL_PLACEMENT) {
        if (tap_place(tp, s)) {
            tp->ex.tap = TP_TAP_NONE;
            tp->ex.sync_active = 0;
            tp->ex.cleared_stop = tp->ex.reg + 1;
            tp_exec_locate(tp);
        }
        return;
    }
    tap_move(tp, s, tap_follow(tp, in, s));
    switch (tp->ex.tap) {
    case TP_TAP_TAPPING:
        if (tp->ex.tap_x >= s->geo.len)
            tp->ex.tap = TP_TAP_REVERSING;
        break;
    case TP_TAP_REVERSING:
        if (turning < 0.0)
            tp->ex.tap = TP_TAP_RETRACTION;
        break;
    case TP_TAP_RETRACTION:
        if (tp->ex.tap_x <= 0.0)
            tp->ex.tap = TP_TAP_FINAL_REVERSAL;
        break;
    default:
        if (turning > 0.0)
            tp->ex.tap = TP_TAP_FINAL_PLACEMENT;
        break;
    }
    tp->ex.tap_revs_prev = revs;
}

/* Commanded position during a rigid tap: along the tap line from its start. */
tp_vec_t tp_sync_tap_position(tp_planner_t *tp)
{
    tp_seg_t *s = tp_seg_at(tp, tp->ex.tap_seg);
    return tp_vec_axpy(&s->geo.u.line.start, tp->ex.tap_x, &s->geo.u.line.dir);
}

/* At the end of the queue: keep the last move open until a locking indexer is locked again. */
int tp_sync_end_hold(tp_planner_t *tp, const tp_cycle_in_t *in)
{
    if (tp->ex.unlock_joint >= 0) {
        tp->ex.unlock_joint = -1;
        tp->ex.relock_pending = 1;
    }
    if (tp->ex.relock_pending && in->indexer_unlocked)
        return 1;
    tp->ex.relock_pending = 0;
    return 0;
}
