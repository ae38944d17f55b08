/* mot_cmd_axis.c: per-axis configuration commands (limits, velocity and acceleration shares, locking joint). */
#include "rtapi.h"
#include "mot_cmd.h"

/* Refuse a negative axis setting. */
static int refuse_negative(const emcmot_command_t *c, double v)
{
    return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "%s axis %d: %g is negative",
                      emcmot_command_name(c->command), c->axis, v);
}

/* SET_AXIS_POSITION_LIMITS. */
int mot_cmd_set_axis_position_limits(const emcmot_command_t *c)
{
    int a = mot_cmd_axis(c);

    if (a < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->min_limit > c->max_limit)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "axis %d: MIN_LIMIT %g is above MAX_LIMIT %g", a, c->min_limit,
                          c->max_limit);
    mot->axis[a].min_limit = c->min_limit;
    mot->axis[a].max_limit = c->max_limit;
    return EMCMOT_COMMAND_OK;
}

/* SET_AXIS_VEL_LIMIT: planner share and external-offset share. */
int mot_cmd_set_axis_vel_limit(const emcmot_command_t *c)
{
    int a = mot_cmd_axis(c);

    if (a < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->vel < 0.0 || c->ext_offset_vel < 0.0)
        return refuse_negative(c, c->vel < 0.0 ? c->vel : c->ext_offset_vel);
    mot->axis[a].vel_limit = c->vel;
    mot->axis[a].ext_offset_vel = c->ext_offset_vel;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SET_AXIS_ACC_LIMIT: planner share and external-offset share. */
int mot_cmd_set_axis_acc_limit(const emcmot_command_t *c)
{
    int a = mot_cmd_axis(c);

    if (a < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->acc < 0.0 || c->ext_offset_acc < 0.0)
        return refuse_negative(c, c->acc < 0.0 ? c->acc : c->ext_offset_acc);
    mot->axis[a].acc_limit = c->acc;
    mot->axis[a].ext_offset_acc = c->ext_offset_acc;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SET_AXIS_LOCKING_JOINT: the joint that locks this rotary axis, -1 none. */
int mot_cmd_set_axis_locking_joint(const emcmot_command_t *c)
{
    int a = mot_cmd_axis(c);

    if (a < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->locking_joint < -1 || c->locking_joint >= mot->max_joints)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "axis %d: locking joint %d is not "
                          "-1..%d", a, c->locking_joint, mot->max_joints - 1);
    mot->axis[a].locking_joint = c->locking_joint;
    return EMCMOT_COMMAND_OK;
}

/* SET_AXIS_JERK_LIMIT. */
int mot_cmd_set_axis_jerk_limit(const emcmot_command_t *c)
{
    int a = mot_cmd_axis(c);

    if (a < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->jerk < 0.0)
        return refuse_negative(c, c->jerk);
    mot->axis[a].jerk_limit = c->jerk;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}
