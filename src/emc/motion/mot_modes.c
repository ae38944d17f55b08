/* mot_modes.c: step 7: enabling/disabling and switching free/teleop/coord once motion is in position. */
#include "rtapi.h"
#include "mot_priv.h"
#include "mot_control.h"
#include "mot_jog.h"
#include "mot_coord.h"

/* Non-zero while a joint's free planner still moves. */
int mot_any_joint_moving(void)
{
    for (int j = 0; j < mot->max_joints; j++)
        if (mot->joint[j].free_tp.active)
            return 1;
    return 0;
}

/* Non-zero while a teleop axis planner still moves. */
static int any_axis_moving(void)
{
    for (int a = 0; a < MOT_NUM_AXES; a++)
        if (mot->axis[a].teleop_tp.active)
            return 1;
    return 0;
}

/* Free planners at rest where the joints are commanded. */
void mot_sync_free_to_cmd(void)
{
    for (int j = 0; j < mot->max_joints; j++) {
        simple_tp_reset(&mot->joint[j].free_tp, mot->joint[j].pos_cmd);
        mot->joint[j].free_tp.enable = 0;
        mot->joint[j].kb_jog_active = mot->joint[j].wheel_jog_active = 0;
    }
}

/* Teleop planners at rest at the commanded pose (without external offsets). */
void mot_sync_teleop_to_cmd(void)
{
    for (int a = 0; a < MOT_NUM_AXES; a++) {
        mot_axis_t *axis = &mot->axis[a];
        simple_tp_reset(&axis->teleop_tp, mot_pose_get(&mot->carte_pos_cmd, a) -
                        axis->ext_offset_tp.curr_pos);
        axis->teleop_tp.enable = 0;
        axis->kb_jog_active = axis->wheel_jog_active = 0;
    }
}

/* Forget every queued segment. */
void mot_clear_planner(void)
{
    EmcPose pos = mot->carte_pos_cmd;

    for (int a = 0; a < MOT_NUM_AXES; a++)
        mot_pose_set(&pos, a, mot_pose_get(&pos, a) - mot->axis[a].ext_offset_tp.curr_pos);
    mot->tp_ops->clear(mot->tp);
    mot->tp_ops->set_pos(mot->tp, &pos);
    mot->queued_end = pos;
    mot->shadow_count = 0;
    mot->probing = 0;
}

/* Motion off: planner cleared, homing cancelled, jogs stopped, spindles off, amps off. */
static void disable(void)
{
    mot->enabled = 0;
    mot->coord = mot->teleop = 0;
    mot->want_coord = mot->want_teleop = 0;
    mot->home->cancel();
    mot_clear_planner();
    for (int j = 0; j < mot->max_joints; j++)
        mot->joint[j].pos_cmd = mot->joint[j].pos_fb;
    mot_sync_free_to_cmd();
    for (int s = 0; s < mot->max_spindles; s++) {
        mot->spindle[s].on = 0;
        mot->spindle[s].direction = 0;
        mot->spindle[s].speed = 0.0;
    }
    mot->paused = mot->stepping = 0;
}

/* Motion on: commands start where the joints are. */
static void enable(void)
{
    for (int j = 0; j < mot->max_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        joint->pos_cmd = joint->pos_fb;
        joint->error = joint->faulted = joint->ferror_tripped = 0;
        cubic_init(&joint->cubic, mot->interp_rate, joint->pos_cmd);
    }
    mot_sync_free_to_cmd();
    mot_forward_kins_cmd();
    mot_sync_teleop_to_cmd();
    mot_clear_planner();
    mot->enabled = 1;
}

/* Enter coordinated mode at the commanded pose. */
static void enter_coord(void)
{
    mot_forward_kins_cmd();
    mot_clear_planner();
    for (int j = 0; j < mot->max_joints; j++) {
        cubic_init(&mot->joint[j].cubic, mot->interp_rate, mot->joint[j].pos_cmd);
        mot->joint[j].override_mask = 0;
    }
    mot->interp_count = 0;
    mot->coord = 1;
    mot->teleop = 0;
}

/* Enter teleop at the commanded pose. */
static void enter_teleop(void)
{
    mot_forward_kins_cmd();
    mot_sync_teleop_to_cmd();
    mot->teleop = 1;
    mot->coord = 0;
}

/* Back to joint mode. */
static void enter_free(void)
{
    mot_sync_free_to_cmd();
    mot->coord = mot->teleop = 0;
}

/* Non-zero when the current mode has come to rest. */
static int at_rest(void)
{
    if (mot->coord)
        return mot_coord_settled();
    if (mot->teleop)
        return !any_axis_moving();
    return !mot_any_joint_moving();
}

/* 7. Mode transitions. */
void mot_mode_transitions(void)
{
    if (!mot->enabling && mot->enabled)
        disable();
    else if (mot->enabling && !mot->enabled)
        enable();
    if (!mot->enabled) {
        mot->motion_state = EMCMOT_MOTION_DISABLED;
        return;
    }
    if (mot->want_coord && !mot->coord && at_rest())
        enter_coord();
    else if (mot->want_teleop && !mot->teleop && at_rest())
        enter_teleop();
    else if (!mot->want_coord && !mot->want_teleop && (mot->coord || mot->teleop) && at_rest())
        enter_free();
    mot->motion_state = mot->coord ? EMCMOT_MOTION_COORD :
        (mot->teleop ? EMCMOT_MOTION_TELEOP : EMCMOT_MOTION_FREE);
}
