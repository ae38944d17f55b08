/* mot_cmd_joint.c: per-joint commands: activation, homing requests, limits, backlash, screw compensation. */
#include "rtapi.h"
#include "mot_cmd.h"
#include "mot_control.h"

/* JOINT_ACTIVATE. */
int mot_cmd_joint_activate(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->joint[j].active = 1;
    return EMCMOT_COMMAND_OK;
}

/* JOINT_DEACTIVATE. */
int mot_cmd_joint_deactivate(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->joint[j].active = 0;
    return EMCMOT_COMMAND_OK;
}

/* JOINT_HOME: joint, or -1 for Home-All; joint mode and enabled only. */
int mot_cmd_joint_home(const emcmot_command_t *c)
{
    if (c->joint < EMCMOT_JOINT_ALL || c->joint >= mot->num_joints)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "cannot home joint %d: not 0..%d",
                          c->joint, mot->num_joints - 1);
    if (!mot->enabled)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 0,
                          "home request for joint %d ignored: motion is disabled", c->joint);
    if (mot->coord || mot->teleop || mot->want_coord || mot->want_teleop)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1, "must be in joint mode to home");
    if (*mot->pins->homing_inhibit)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1,
                          "Homing denied by motion.homing-inhibit joint=%d\n", c->joint);
    if (mot->home->home_joint(c->joint) < 0)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 0, "homing module refused joint %d",
                          c->joint);
    return EMCMOT_COMMAND_OK;
}

/* JOINT_UNHOME: joint, -1 all, -2 VOLATILE_HOME joints. */
int mot_cmd_joint_unhome(const emcmot_command_t *c)
{
    if (c->joint < EMCMOT_JOINT_VOLATILE || c->joint >= mot->num_joints)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "cannot unhome joint %d: not 0..%d",
                          c->joint, mot->num_joints - 1);
    if (mot->enabled && (mot->coord || mot->teleop))
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1,
                          "must be in joint mode or disabled to unhome");
    mot_homing_inputs_update();
    if (mot->home->set_unhomed(c->joint, mot->enabled) < 0)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 0, "homing module refused to unhome %d",
                          c->joint);
    return EMCMOT_COMMAND_OK;
}

/* Refuse v < 0 for the command's joint setting. */
static int refuse_negative(const emcmot_command_t *c, double v)
{
    return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "%s joint %d: %g is negative",
                      emcmot_command_name(c->command), c->joint, v);
}

/* SET_JOINT_POSITION_LIMITS. */
int mot_cmd_set_joint_position_limits(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->min_limit > c->max_limit)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "joint %d: MIN_LIMIT %g is above MAX_LIMIT %g", j, c->min_limit,
                          c->max_limit);
    mot->joint[j].min_limit = c->min_limit;
    mot->joint[j].max_limit = c->max_limit;
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_BACKLASH. */
int mot_cmd_set_joint_backlash(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->backlash < 0.0)
        return refuse_negative(c, c->backlash);
    mot->joint[j].backlash = c->backlash;
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_MIN_FERROR. */
int mot_cmd_set_joint_min_ferror(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->min_ferror < 0.0)
        return refuse_negative(c, c->min_ferror);
    mot->joint[j].min_ferror = c->min_ferror;
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_MAX_FERROR. */
int mot_cmd_set_joint_max_ferror(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->max_ferror < 0.0)
        return refuse_negative(c, c->max_ferror);
    mot->joint[j].max_ferror = c->max_ferror;
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_VEL_LIMIT: joint-mode velocity (jogs, homing, following-error scale). */
int mot_cmd_set_joint_vel_limit(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->vel < 0.0)
        return refuse_negative(c, c->vel);
    mot->joint[j].vel_limit = c->vel;
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_ACC_LIMIT. */
int mot_cmd_set_joint_acc_limit(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->acc < 0.0)
        return refuse_negative(c, c->acc);
    mot->joint[j].acc_limit = c->acc;
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_JERK_LIMIT. */
int mot_cmd_set_joint_jerk_limit(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->jerk < 0.0)
        return refuse_negative(c, c->jerk);
    mot->joint[j].jerk_limit = c->jerk;
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_HOMING_PARAMS: handed to the homing module. */
int mot_cmd_set_joint_homing_params(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);
    home_params_t p;

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    p.home_offset = c->home_offset;
    p.home = c->home;
    p.home_final_vel = c->home_final_vel;
    p.home_search_vel = c->home_search_vel;
    p.home_latch_vel = c->home_latch_vel;
    p.home_flags = c->home_flags;
    p.home_sequence = c->home_sequence;
    p.volatile_home = c->volatile_home;
    if (mot->home->set_params(j, &p) < 0)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "homing module refused the "
                          "parameters of joint %d", j);
    mot->joint[j].locking_indexer = (c->home_flags & EMCMOT_HOME_UNLOCK_FIRST) != 0;
    return EMCMOT_COMMAND_OK;
}

/* UPDATE_JOINT_HOMING_PARAMS: home offset, home and sequence changed at run time (ini.* pins). */
int mot_cmd_update_joint_homing_params(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (mot->home->update_params(j, c->home_offset, c->home, c->home_sequence) < 0)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "homing module refused the update "
                          "of joint %d", j);
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_MOTOR_OFFSET. */
int mot_cmd_set_joint_motor_offset(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->joint[j].motor_offset = c->offset;
    return EMCMOT_COMMAND_OK;
}

/* SET_JOINT_COMP: one row of the screw-compensation table (nominal increasing, <= 256 rows). */
int mot_cmd_set_joint_comp(const emcmot_command_t *c)
{
    int j = mot_cmd_joint(c);
    int rc;

    if (j < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    rc = comp_table_add(&mot->joint[j].comp, c->comp_nominal, c->comp_forward, c->comp_reverse);
    if (rc == -ENOSPC)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "joint %d: too many compensation entries", j);
    if (rc < 0)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "joint %d: compensation values must increase", j);
    return EMCMOT_COMMAND_OK;
}
