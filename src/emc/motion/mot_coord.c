/* mot_coord.c: coordinated mode: one planner cycle, synced outputs, inverse kinematics, cubic interpolation. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"
#include "mot_coord.h"

static tp_cycle_in_t cycle_in;
static tp_cycle_out_t cycle_out;

/* What the planner reads this cycle. */
static void fill_cycle_in(void)
{
    double af = *mot->pins->adaptive_feed, lim = mot->max_feed_override;

    cycle_in.feed_scale = mot->feed_scale;
    cycle_in.rapid_scale = mot->rapid_scale;
    cycle_in.adaptive_feed = isfinite(af) ? fmax(-lim, fmin(lim, af)) : 0.0;
    cycle_in.feed_hold = *mot->pins->feed_hold != 0;
    cycle_in.feed_inhibit = *mot->pins->feed_inhibit != 0;
    cycle_in.num_spindles = mot->num_spindles;
    for (int s = 0; s < mot->num_spindles; s++) {
        const mot_spindle_t *sp = &mot->spindle[s];
        tp_spindle_in_t *in = &cycle_in.spindle[s];
        in->revs = sp->revs;
        in->speed_rps = sp->speed_fb_rps;
        in->speed_cmd_rps = sp->speed_out / 60.0;
        in->at_speed = sp->at_speed;
        in->index_enable = *mot->pins->spindle[s].index_enable != 0;
    }
    /* Not unlocked until the planner has named the joint and its is-unlocked pin answered
     * (a joint without the pin counts as unlocked once named). */
    cycle_in.indexer_unlocked = 0;
    if (mot->indexer_joint >= 0)
        cycle_in.indexer_unlocked = !mot->pins->joint[mot->indexer_joint].is_unlocked ||
            *mot->pins->joint[mot->indexer_joint].is_unlocked;
}

/* Synchronised digital/analog outputs that take effect this cycle. */
static void apply_synced_io(const tp_cycle_out_t *o)
{
    for (int i = 0; i < mot->num_dio; i++)
        if (o->dout_change_mask & (1ull << i))
            mot->dout[i] = (o->dout_values >> i) & 1u;
    for (int i = 0; i < mot->num_aio; i++)
        if (o->aout_change_mask & (1ull << i))
            mot->aout[i] = o->aout_values[i];
}

/* Spindle index arming, rigid-tap reversal and indexer unlock requests. */
static void apply_requests(const tp_cycle_out_t *o)
{
    for (int s = 0; s < mot->num_spindles; s++) {
        if (o->arm_index[s])
            *mot->pins->spindle[s].index_enable = 1;
        mot->spindle[s].tap_reverse = o->spindle_reverse[s];
    }
    if (mot->indexer_joint >= 0 && mot->indexer_joint != o->unlock_joint &&
        mot->pins->joint[mot->indexer_joint].unlock)
        *mot->pins->joint[mot->indexer_joint].unlock = 0;
    mot->indexer_joint = o->unlock_joint;
    if (o->unlock_joint >= 0 && o->unlock_joint < mot->max_joints &&
        mot->pins->joint[o->unlock_joint].unlock)
        *mot->pins->joint[o->unlock_joint].unlock = 1;
}

/* Drop remembered segments that have finished; the front one is executing. */
static void shadow_follow(int32_t exec_id)
{
    while (mot->shadow_count > 1 && mot->shadow[mot->shadow_head].id != exec_id) {
        mot->shadow_head = (mot->shadow_head + 1) % MOT_TP_QUEUE_SIZE;
        mot->shadow_count--;
    }
    if (cycle_out.done)
        mot->shadow_count = 0;
}

/* Copy the planner's report into the controller. */
static void take_report(const tp_cycle_out_t *o)
{
    mot->current_vel = o->current_vel;
    mot->requested_vel = o->requested_vel;
    mot->distance_to_go = o->distance_to_go;
    mot->dtg = o->dtg;
    mot->net_feed_scale = o->net_feed_scale;
    mot->motion_type = o->done ? TP_MOTION_IDLE : o->motion_type;
    mot->exec_id = o->exec_id;
    mot->exec_tag = o->exec_tag;
    mot->queue_depth = o->queue_depth;
    mot->active_depth = o->active_depth;
    mot->queue_full = o->queue_full;
    mot->spindle_sync_waiting = o->spindle_sync_waiting;
    mot->reverse_running = o->reverse;
    if (mot->stepping && o->exec_id != mot->step_id) {
        mot->tp_ops->pause(mot->tp);
        mot->paused = 1;
        mot->stepping = 0;
    }
    shadow_follow(o->exec_id);
}

/* One planner cycle: its pose plus external offsets to joints; 0 or -1. */
static int planner_cycle(double *joints)
{
    EmcPose pos;

    fill_cycle_in();
    if (mot->paused)
        mot->tp_ops->pause(mot->tp);    /* motion's pause holds even across a finishing abort */
    mot->tp_ops->run_cycle(mot->tp, &cycle_in, &cycle_out);
    take_report(&cycle_out);
    apply_synced_io(&cycle_out);
    apply_requests(&cycle_out);
    mot->coord_pos = cycle_out.pos;
    pos = cycle_out.pos;
    mot_eoffset_apply(&pos);
    if (mot_pose_to_joints(&pos, joints) < 0)
        return -1;
    mot->carte_pos_cmd = pos;
    return 0;
}

/* Coordinated mode: a planner point every trajectory period, cubic samples in between. */
void mot_coord_cmds(void)
{
    double joints[MOT_MAX_JOINTS] = { 0 };

    if (mot->interp_rate <= 1) {
        if (planner_cycle(joints) == 0)
            for (int j = 0; j < mot->num_kins_joints; j++)
                mot_joint_set_cmd(&mot->joint[j], joints[j]);
        return;
    }
    if (cubic_needs_point(&mot->joint[0].cubic)) {
        if (planner_cycle(joints) < 0)
            return;
        for (int j = 0; j < mot->num_kins_joints; j++)
            cubic_add_point(&mot->joint[j].cubic, joints[j]);
    }
    for (int j = 0; j < mot->num_kins_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        double pos = cubic_sample(&joint->cubic, mot->servo_period, NULL, NULL);
        mot_joint_set_cmd(joint, pos);
    }
}

/* The segment executing now as remembered at queue time, or NULL. */
const mot_shadow_seg_t *mot_executing_segment(void)
{
    if (!mot->coord || mot->shadow_count == 0)
        return NULL;
    if (mot->shadow[mot->shadow_head].id != mot->exec_id)
        return NULL;
    return &mot->shadow[mot->shadow_head];
}

/* Coordinated motion at rest: the planner is done and the joints' interpolation caught up. */
int mot_coord_settled(void)
{
    if (!mot->tp_ops->is_done(mot->tp))
        return 0;
    for (int j = 0; j < mot->num_kins_joints && mot->interp_rate > 1; j++)
        if (!cubic_settled(&mot->joint[j].cubic))
            return 0;
    return 1;
}
