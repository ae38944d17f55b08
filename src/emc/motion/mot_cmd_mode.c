/* mot_cmd_mode.c: commands that change modes and machine-wide state (abort, enable, free/coord/teleop, pause). */
#include "rtapi.h"
#include "mot_cmd.h"

/* ABORT: stop what the current mode runs; clear joint error flags. */
int mot_cmd_abort(const emcmot_command_t *c)
{
    (void)c;
    if (mot->teleop) {
        for (int a = 0; a < MOT_NUM_AXES; a++) {
            mot->axis[a].teleop_tp.enable = 0;
            mot->axis[a].kb_jog_active = mot->axis[a].wheel_jog_active = 0;
        }
    } else if (mot->coord) {
        mot->tp_ops->abort(mot->tp);
        mot->probing = 0;
    } else {
        mot_abort_jogs();
        mot->home->cancel();
    }
    mot->paused = 0;
    mot->stepping = 0;
    for (int j = 0; j < mot->max_joints; j++)
        mot->joint[j].error = 0;
    *mot->pins->coord_error = 0;
    return EMCMOT_COMMAND_OK;
}

/* ENABLE: machine on, unless motion.enable holds it off. */
int mot_cmd_enable(const emcmot_command_t *c)
{
    (void)c;
    if (!*mot->pins->enable)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1,
                          "can't enable motion, enable input is false");
    mot->enabling = 1;
    mot->fault_code = EMCMOT_FAULT_NONE;
    for (int j = 0; j < mot->max_joints; j++)
        mot->joint[j].ferror_high_mark = 0.0;
    return EMCMOT_COMMAND_OK;
}

/* DISABLE: machine off (the controller stops everything next cycle). */
int mot_cmd_disable(const emcmot_command_t *c)
{
    (void)c;
    mot->enabling = 0;
    return EMCMOT_COMMAND_OK;
}

/* PAUSE: hold the coordinated queue. */
int mot_cmd_pause(const emcmot_command_t *c)
{
    (void)c;
    mot->tp_ops->pause(mot->tp);
    mot->paused = 1;
    mot->stepping = 0;
    return EMCMOT_COMMAND_OK;
}

/* RESUME: release a pause or a single step. */
int mot_cmd_resume(const emcmot_command_t *c)
{
    (void)c;
    mot->stepping = 0;
    mot->paused = 0;
    mot->tp_ops->resume(mot->tp);
    return EMCMOT_COMMAND_OK;
}

/* STEP: run until the next segment starts, then pause again. */
int mot_cmd_step(const emcmot_command_t *c)
{
    (void)c;
    mot->stepping = 1;
    mot->step_id = mot->exec_id;
    mot->paused = 0;
    mot->tp_ops->resume(mot->tp);
    return EMCMOT_COMMAND_OK;
}

/* REVERSE: run back along executed segments. */
int mot_cmd_reverse(const emcmot_command_t *c)
{
    (void)c;
    mot->reverse = 1;
    mot->tp_ops->set_run_dir(mot->tp, 1);
    return EMCMOT_COMMAND_OK;
}

/* FORWARD: run forward again. */
int mot_cmd_forward(const emcmot_command_t *c)
{
    (void)c;
    mot->reverse = 0;
    mot->tp_ops->set_run_dir(mot->tp, 0);
    return EMCMOT_COMMAND_OK;
}

/* FREE: joint mode once motion is in position. */
int mot_cmd_free(const emcmot_command_t *c)
{
    (void)c;
    mot->want_coord = 0;
    mot->want_teleop = 0;
    return EMCMOT_COMMAND_OK;
}

/* COORD: planner mode; non-identity kinematics need every joint homed. */
int mot_cmd_coord(const emcmot_command_t *c)
{
    (void)c;
    if (mot_kins_homing_required() && !mot_joints_homed())
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1,
                          "all joints must be homed before going into coordinated mode");
    mot->want_coord = 1;
    mot->want_teleop = 0;
    for (int j = 0; j < mot->max_joints; j++)
        mot->joint[j].override_mask = 0;
    return EMCMOT_COMMAND_OK;
}

/* TELEOP: world jog mode; non-identity kinematics need every joint homed. */
int mot_cmd_teleop(const emcmot_command_t *c)
{
    (void)c;
    if (mot_kins_homing_required() && !mot_joints_homed())
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1,
                          "all joints must be homed before going into teleop mode");
    mot->want_teleop = 1;
    mot->want_coord = 0;
    return EMCMOT_COMMAND_OK;
}

/* OVERRIDE_LIMITS: mask the switches tripped now (joint -1: all joints), or end the mask. */
int mot_cmd_override_limits(const emcmot_command_t *c)
{
    int first = c->joint < 0 ? 0 : c->joint;
    int last = c->joint < 0 ? mot->max_joints - 1 : c->joint;

    if (c->joint >= mot->max_joints)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "OVERRIDE_LIMITS: joint %d is not 0..%d",
                          c->joint, mot->max_joints - 1);
    for (int j = first; j <= last; j++) {
        mot_joint_t *joint = &mot->joint[j];
        joint->override_mask = c->enable && (joint->pos_hard || joint->neg_hard);
    }
    return EMCMOT_COMMAND_OK;
}

/* SET_NUM_JOINTS: joints in use (at most the num_joints module parameter). */
int mot_cmd_set_num_joints(const emcmot_command_t *c)
{
    if (c->count < 1 || c->count > mot->max_joints || c->count < mot->num_extra_joints)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "SET_NUM_JOINTS %d: motmod was loaded with num_joints=%d "
                          "(num_extrajoints=%d)", c->count, mot->max_joints,
                          mot->num_extra_joints);
    mot->num_joints = c->count;
    mot->num_kins_joints = c->count - mot->num_extra_joints;
    mot->home->set_num_joints(c->count);
    return EMCMOT_COMMAND_OK;
}

/* SET_NUM_SPINDLES: spindles in use; more than loaded is reported and clamped. */
int mot_cmd_set_num_spindles(const emcmot_command_t *c)
{
    if (c->count < 0)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "SET_NUM_SPINDLES %d", c->count);
    if (c->count > mot->max_spindles) {
        mot_report("Problem:\n  motmod configured for %d spindles\n  but command requests %d "
                   "spindles\n  Using: %d spindles", mot->max_spindles, c->count,
                   mot->max_spindles);
        mot->num_spindles = mot->max_spindles;
        return EMCMOT_COMMAND_OK;
    }
    mot->num_spindles = c->count;
    return EMCMOT_COMMAND_OK;
}

/* SET_WORLD_HOME: world pose of the home position (non-identity kinematics). */
int mot_cmd_set_world_home(const emcmot_command_t *c)
{
    mot->world_home = c->pos;
    return EMCMOT_COMMAND_OK;
}

/* SET_DEBUG: debug level shown in the status. */
int mot_cmd_set_debug(const emcmot_command_t *c)
{
    mot->debug = c->debug;
    return EMCMOT_COMMAND_OK;
}

/* SET_OFFSET: tool offset for motion.tooloffset.*. */
int mot_cmd_set_offset(const emcmot_command_t *c)
{
    mot->tool_offset = c->pos;
    return EMCMOT_COMMAND_OK;
}
