/* mot_cmd_jog.c: keyboard jogs (continuous, incremental, absolute, abort) for joints and teleop axes. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_cmd.h"
#include "mot_jog.h"

typedef enum jog_kind { JOG_CONT, JOG_INCR, JOG_ABS } jog_kind_t;

/* Text of the kind for messages. */
static const char *jog_name(jog_kind_t kind)
{
    static const char *const names[] = { "JOG_CONT", "JOG_INCR", "JOG_ABS" };
    return names[kind];
}

/* Direction a joint jog moves: the velocity's sign, or toward the target of an absolute jog. */
static double jog_direction(const emcmot_command_t *c, jog_kind_t kind, double from)
{
    if (kind == JOG_ABS)
        return c->offset - from;
    return c->vel;
}

/* Refusals shared by joint jogs; the joint, or -1 after refusing. */
static int joint_jog_refusals(const emcmot_command_t *c, jog_kind_t kind)
{
    int j = c->joint;

    if (j < 0 || j >= mot->num_joints) {
        mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                   "Joint jog requested for undefined joint number=%d (min=0,max=%d)", j,
                   mot->num_joints - 1);
        return -1;
    }
    if (mot->coord) {
        mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1, "Can't jog joint in coordinated mode.");
        return -1;
    }
    if (mot->home->homing_active()) {
        mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1, kind == JOG_INCR ?
                   "Can't jog any joint while homing." : "Can't jog any joints while homing.");
        return -1;
    }
    if (mot_joint_jog_refused(j, jog_direction(c, kind, mot->joint[j].pos_cmd), 1))
        return -1;
    return j;
}

/* Where a joint jog goes; 0, or -1 when an incremental target lies outside (ignored). */
static int joint_jog_target(int j, const emcmot_command_t *c, jog_kind_t kind, double *target)
{
    mot_joint_t *joint = &mot->joint[j];
    double lo, hi, base;

    mot_joint_jog_limits(j, &lo, &hi);
    base = joint->free_tp.active ? joint->free_tp.pos_cmd : joint->pos_cmd;
    switch (kind) {
    case JOG_CONT:
        *target = c->vel > 0.0 ? hi : lo;
        return 0;
    case JOG_INCR:
        *target = c->vel > 0.0 ? base + c->offset : base - c->offset;
        return (*target > hi || *target < lo) ? -1 : 0;
    default:
        *target = c->offset > hi ? hi : (c->offset < lo ? lo : c->offset);
        return 0;
    }
}

/* A keyboard jog of joint c->joint. */
static int joint_jog(const emcmot_command_t *c, jog_kind_t kind)
{
    int j = joint_jog_refusals(c, kind);
    mot_joint_t *joint;
    double target;

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_COMMAND;
    joint = &mot->joint[j];
    if (joint->wheel_jog_active || mot->net_feed_scale < 0.0001)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 0,
                          "joint %d: wheel jog active or feed scale zero", j);
    if (joint_jog_target(j, c, kind, &target) < 0)
        return EMCMOT_COMMAND_OK;
    joint->free_tp.pos_cmd = target;
    joint->free_tp.max_vel = fmin(fabs(c->vel), joint->vel_limit);
    joint->free_tp.enable = 1;
    joint->kb_jog_active = 1;
    joint->error = 0;
    if (mot->kins->type() == KINEMATICS_INVERSE_ONLY)
        mot->home->set_unhomed(j, mot->enabled);
    return EMCMOT_COMMAND_OK;
}

/* Refusals of a teleop axis jog; the axis or -1. */
static int axis_jog_refusals(const emcmot_command_t *c, jog_kind_t kind)
{
    if (c->joint >= 0) {
        mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1, "%s Mode is TELEOP, cannot jog joint\n",
                   jog_name(kind));
        return -1;
    }
    if (c->axis < 0 || c->axis >= MOT_NUM_AXES) {
        mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "Axis jog requested for undefined axis %d",
                   c->axis);
        return -1;
    }
    if (mot_axis_jog_refused(c->axis, 1))
        return -1;
    return c->axis;
}

/* A keyboard jog of a world axis in teleop mode (always inside the axis limits). */
static int axis_jog(const emcmot_command_t *c, jog_kind_t kind)
{
    int a = axis_jog_refusals(c, kind);
    mot_axis_t *axis;
    double base, target;

    if (a < 0)
        return EMCMOT_COMMAND_INVALID_COMMAND;
    axis = &mot->axis[a];
    if (axis->wheel_jog_active)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 0, "axis %d: wheel jog active", a);
    base = axis->teleop_tp.active ? axis->teleop_tp.pos_cmd : axis->teleop_tp.curr_pos;
    if (kind == JOG_CONT)
        target = c->vel > 0.0 ? axis->max_limit : axis->min_limit;
    else if (kind == JOG_INCR)
        target = c->vel > 0.0 ? base + c->offset : base - c->offset;
    else
        target = c->offset;
    if (kind == JOG_INCR && (target > axis->max_limit || target < axis->min_limit))
        return EMCMOT_COMMAND_OK;
    target = fmin(fmax(target, axis->min_limit), axis->max_limit);
    axis->teleop_tp.pos_cmd = target;
    axis->teleop_tp.max_vel = fmin(fabs(c->vel), axis->vel_limit);
    axis->teleop_tp.max_acc = axis->acc_limit;
    axis->teleop_tp.enable = 1;
    axis->kb_jog_active = 1;
    return EMCMOT_COMMAND_OK;
}

/* Dispatch a jog by mode. */
static int jog(const emcmot_command_t *c, jog_kind_t kind)
{
    if (mot->teleop)
        return axis_jog(c, kind);
    return joint_jog(c, kind);
}

/* JOG_CONT. */
int mot_cmd_jog_cont(const emcmot_command_t *c)
{
    return jog(c, JOG_CONT);
}

/* JOG_INCR. */
int mot_cmd_jog_incr(const emcmot_command_t *c)
{
    return jog(c, JOG_INCR);
}

/* JOG_ABS. */
int mot_cmd_jog_abs(const emcmot_command_t *c)
{
    return jog(c, JOG_ABS);
}

/* JOG_ABORT: decelerate a jog of the axis (teleop) or joint (free); it ends when stopped. */
int mot_cmd_jog_abort(const emcmot_command_t *c)
{
    if (mot->teleop && c->axis >= 0 && c->axis < MOT_NUM_AXES) {
        mot_axis_t *axis = &mot->axis[c->axis];
        axis->teleop_tp.enable = 0;
        return EMCMOT_COMMAND_OK;
    }
    if (c->joint >= 0 && c->joint < mot->num_joints && !mot->home->joint_homing(c->joint)) {
        mot_joint_t *joint = &mot->joint[c->joint];
        if (joint->kb_jog_active || joint->wheel_jog_active)
            joint->free_tp.enable = 0;
    }
    return EMCMOT_COMMAND_OK;
}
