/* mot_poscmd.c: step 11: commanded joint positions in each mode, and the runtime soft-limit check. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"
#include "mot_coord.h"

/* Disable motion because inverse kinematics failed (code from mot_inverse_kins). */
static void kins_failed(int code)
{
    if (code == -1)
        mot_report("kinematicsInverse failed");
    else
        mot_report("kinematicsInverse gave non-finite joint location on joint %d", -code - 2);
    mot->enabling = 0;
    mot->fault_code = EMCMOT_FAULT_KINEMATICS;
}

/* Set the kinematic joints' commands from a world pose; 0 or -1 after disabling. */
int mot_pose_to_joints(const EmcPose *pos, double *joints)
{
    for (int j = 0; j < mot->max_joints; j++)
        joints[j] = mot->joint[j].pos_cmd;
    int rc = mot_inverse_kins(pos, joints);
    if (rc != 0) {
        kins_failed(rc);
        return -1;
    }
    return 0;
}

/* Update a joint command with velocity, acceleration and jerk from the change. */
void mot_joint_set_cmd(mot_joint_t *joint, double pos)
{
    double vel = (pos - joint->pos_cmd) / mot->servo_period;
    double acc = (vel - joint->vel_cmd) / mot->servo_period;

    joint->jerk_cmd = (acc - joint->acc_cmd) / mot->servo_period;
    joint->acc_cmd = acc;
    joint->vel_cmd = vel;
    joint->pos_cmd = pos;
}

/* Clear jog flags of planners that came to rest; a finished jog ends the limit override. */
static void joint_jog_finished(mot_joint_t *joint)
{
    if (joint->free_tp.active || (!joint->kb_jog_active && !joint->wheel_jog_active))
        return;
    joint->kb_jog_active = joint->wheel_jog_active = 0;
    for (int j = 0; j < mot->max_joints; j++)
        mot->joint[j].override_mask = 0;
}

/* Free mode: each joint follows its own trapezoid planner. */
static void free_cmds(void)
{
    for (int j = 0; j < mot->num_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        simple_tp_t *tp = &joint->free_tp;
        double acc = fmin(joint->acc_limit, mot->acc);

        if (joint->wheel_jog_active)
            acc *= joint->wheel_accel_fraction;
        tp->max_acc = acc;
        simple_tp_update(tp, mot->servo_period);
        joint->pos_cmd = tp->curr_pos;
        joint->jerk_cmd = (tp->curr_acc - joint->acc_cmd) / mot->servo_period;
        joint->vel_cmd = tp->curr_vel;
        joint->acc_cmd = tp->curr_acc;
        joint_jog_finished(joint);
    }
    mot_forward_kins_cmd();
}

/* Teleop: per-axis planners, external offsets, inverse kinematics. */
static void teleop_cmds(void)
{
    double joints[MOT_MAX_JOINTS] = { 0 };
    EmcPose pos;

    for (int a = 0; a < MOT_NUM_AXES; a++) {
        mot_axis_t *axis = &mot->axis[a];
        simple_tp_update(&axis->teleop_tp, mot->servo_period);
        mot_pose_set(&pos, a, axis->teleop_tp.curr_pos);
        if (!axis->teleop_tp.active)
            axis->kb_jog_active = axis->wheel_jog_active = 0;
    }
    mot_eoffset_apply(&pos);
    if (mot_pose_to_joints(&pos, joints) < 0)
        return;
    mot->carte_pos_cmd = pos;
    for (int j = 0; j < mot->num_kins_joints; j++)
        mot_joint_set_cmd(&mot->joint[j], joints[j]);
}

/* Disabled: commands follow the feedback so enabling never jumps. */
static void disabled_cmds(void)
{
    for (int j = 0; j < mot->max_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        joint->pos_cmd = joint->pos_fb;
        joint->vel_cmd = joint->acc_cmd = joint->jerk_cmd = 0.0;
        simple_tp_reset(&joint->free_tp, joint->pos_fb);
    }
    if (mot->carte_pos_fb_ok)
        mot->carte_pos_cmd = mot->carte_pos_fb;
}

/* Extra joints: once homed they follow joint.N.posthome-cmd (outside homing). */
static void extra_joint_cmds(void)
{
    for (int j = mot->num_kins_joints; j < mot->num_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        hal_float_t *posthome = mot->pins->joint[j].posthome_cmd;
        if (!posthome || !mot->home->joint_homed(j) || mot->home->joint_homing(j))
            continue;
        if (isfinite(*posthome))
            mot_joint_set_cmd(joint, *posthome);
        simple_tp_reset(&joint->free_tp, joint->pos_cmd);
    }
}

/* Extra joints outside free mode still run their own planners (jogs finish, homing). */
static void extra_joint_planners(void)
{
    for (int j = mot->num_kins_joints; j < mot->num_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        joint->free_tp.max_acc = fmin(joint->acc_limit, mot->acc);
        simple_tp_update(&joint->free_tp, mot->servo_period);
        joint->pos_cmd = joint->free_tp.curr_pos;
        joint->vel_cmd = joint->free_tp.curr_vel;
    }
}

/* 11. Commanded positions for the mode in force. */
void mot_get_pos_cmds(void)
{
    if (!mot->enabled) {
        disabled_cmds();
        return;
    }
    if (mot->coord) {
        mot_coord_cmds();
        extra_joint_planners();
    } else if (mot->teleop) {
        teleop_cmds();
        extra_joint_planners();
    } else {
        free_cmds();
    }
    extra_joint_cmds();
}

/* Report a homed joint leaving its soft limits and stop the motion that took it there. */
static void soft_limit_hit(int j, int positive, double limit)
{
    mot_report("Exceeded %s soft limit (%.5f) on joint %d\n", positive ? "POSITIVE" : "NEGATIVE",
               limit, j);
    if (mot->kins->type() == KINEMATICS_IDENTITY)
        mot_report("Joint must be unhomed, jogged into limits, rehomed");
    else
        mot_report("Hint: switch to joint mode to jog off soft limit");
    if (mot->coord)
        mot->tp_ops->abort(mot->tp);
    else if (mot->teleop)
        for (int a = 0; a < MOT_NUM_AXES; a++)
            mot->axis[a].teleop_tp.enable = 0;
}

/* Runtime soft limits of homed joints (coordinated arcs may bulge past them). */
void mot_check_soft_limits(void)
{
    int any = 0;

    for (int j = 0; j < mot->num_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        int homed = mot->home->joint_homed(j) && joint->active;
        int pos = homed && joint->pos_cmd > joint->max_limit + 1e-9;
        int neg = homed && joint->pos_cmd < joint->min_limit - 1e-9;
        if (mot->enabled && (mot->coord || mot->teleop)) {
            if (pos && !joint->pos_soft)
                soft_limit_hit(j, 1, joint->max_limit);
            if (neg && !joint->neg_soft)
                soft_limit_hit(j, 0, joint->min_limit);
        }
        joint->pos_soft = pos;
        joint->neg_soft = neg;
        any |= pos || neg;
    }
    mot->on_soft_limit = any;
}
