/* mot_command.c: motion-command-handler: drain the command ring (bounded), dispatch by table, echo results. */
#include <stdarg.h>
#include "rtapi.h"
#include "mot_cmd.h"

/* Handler of every code; index = code. */
static const mot_cmd_fn_t handlers[EMCMOT_LAST_COMMAND + 1] = {
    [EMCMOT_ABORT] = mot_cmd_abort,
    [EMCMOT_ENABLE] = mot_cmd_enable,
    [EMCMOT_DISABLE] = mot_cmd_disable,
    [EMCMOT_PAUSE] = mot_cmd_pause,
    [EMCMOT_REVERSE] = mot_cmd_reverse,
    [EMCMOT_FORWARD] = mot_cmd_forward,
    [EMCMOT_RESUME] = mot_cmd_resume,
    [EMCMOT_STEP] = mot_cmd_step,
    [EMCMOT_FREE] = mot_cmd_free,
    [EMCMOT_COORD] = mot_cmd_coord,
    [EMCMOT_TELEOP] = mot_cmd_teleop,
    [EMCMOT_SPINDLE_SCALE] = mot_cmd_spindle_scale,
    [EMCMOT_SS_ENABLE] = mot_cmd_ss_enable,
    [EMCMOT_FEED_SCALE] = mot_cmd_feed_scale,
    [EMCMOT_RAPID_SCALE] = mot_cmd_rapid_scale,
    [EMCMOT_FS_ENABLE] = mot_cmd_fs_enable,
    [EMCMOT_FH_ENABLE] = mot_cmd_fh_enable,
    [EMCMOT_AF_ENABLE] = mot_cmd_af_enable,
    [EMCMOT_OVERRIDE_LIMITS] = mot_cmd_override_limits,
    [EMCMOT_SET_LINE] = mot_cmd_set_line,
    [EMCMOT_SET_CIRCLE] = mot_cmd_set_circle,
    [EMCMOT_CLEAR_PROBE_FLAGS] = mot_cmd_clear_probe_flags,
    [EMCMOT_PROBE] = mot_cmd_probe,
    [EMCMOT_RIGID_TAP] = mot_cmd_rigid_tap,
    [EMCMOT_SET_VEL] = mot_cmd_set_vel,
    [EMCMOT_SET_VEL_LIMIT] = mot_cmd_set_vel_limit,
    [EMCMOT_SET_ACC] = mot_cmd_set_acc,
    [EMCMOT_SET_JERK] = mot_cmd_set_jerk,
    [EMCMOT_SET_PLANNER_TYPE] = mot_cmd_set_planner_type,
    [EMCMOT_SET_SCURVE_PEAK_SCALE] = mot_cmd_set_scurve_peak_scale,
    [EMCMOT_SET_TERM_COND] = mot_cmd_set_term_cond,
    [EMCMOT_SET_NUM_JOINTS] = mot_cmd_set_num_joints,
    [EMCMOT_SET_NUM_SPINDLES] = mot_cmd_set_num_spindles,
    [EMCMOT_SET_WORLD_HOME] = mot_cmd_set_world_home,
    [EMCMOT_SET_DEBUG] = mot_cmd_set_debug,
    [EMCMOT_SET_DOUT] = mot_cmd_set_dout,
    [EMCMOT_SET_AOUT] = mot_cmd_set_aout,
    [EMCMOT_SET_SPINDLESYNC] = mot_cmd_set_spindlesync,
    [EMCMOT_SPINDLE_ON] = mot_cmd_spindle_on,
    [EMCMOT_SPINDLE_OFF] = mot_cmd_spindle_off,
    [EMCMOT_SPINDLE_INCREASE] = mot_cmd_spindle_increase,
    [EMCMOT_SPINDLE_DECREASE] = mot_cmd_spindle_decrease,
    [EMCMOT_SPINDLE_BRAKE_ENGAGE] = mot_cmd_spindle_brake_engage,
    [EMCMOT_SPINDLE_BRAKE_RELEASE] = mot_cmd_spindle_brake_release,
    [EMCMOT_SPINDLE_ORIENT] = mot_cmd_spindle_orient,
    [EMCMOT_SET_OFFSET] = mot_cmd_set_offset,
    [EMCMOT_SET_MAX_FEED_OVERRIDE] = mot_cmd_set_max_feed_override,
    [EMCMOT_SETUP_ARC_BLENDS] = mot_cmd_setup_arc_blends,
    [EMCMOT_SET_PROBE_ERR_INHIBIT] = mot_cmd_set_probe_err_inhibit,
    [EMCMOT_JOG_CONT] = mot_cmd_jog_cont,
    [EMCMOT_JOG_INCR] = mot_cmd_jog_incr,
    [EMCMOT_JOG_ABS] = mot_cmd_jog_abs,
    [EMCMOT_JOG_ABORT] = mot_cmd_jog_abort,
    [EMCMOT_JOINT_ACTIVATE] = mot_cmd_joint_activate,
    [EMCMOT_JOINT_DEACTIVATE] = mot_cmd_joint_deactivate,
    [EMCMOT_JOINT_HOME] = mot_cmd_joint_home,
    [EMCMOT_JOINT_UNHOME] = mot_cmd_joint_unhome,
    [EMCMOT_SET_JOINT_POSITION_LIMITS] = mot_cmd_set_joint_position_limits,
    [EMCMOT_SET_JOINT_BACKLASH] = mot_cmd_set_joint_backlash,
    [EMCMOT_SET_JOINT_MIN_FERROR] = mot_cmd_set_joint_min_ferror,
    [EMCMOT_SET_JOINT_MAX_FERROR] = mot_cmd_set_joint_max_ferror,
    [EMCMOT_SET_JOINT_VEL_LIMIT] = mot_cmd_set_joint_vel_limit,
    [EMCMOT_SET_JOINT_ACC_LIMIT] = mot_cmd_set_joint_acc_limit,
    [EMCMOT_SET_JOINT_HOMING_PARAMS] = mot_cmd_set_joint_homing_params,
    [EMCMOT_SET_JOINT_JERK_LIMIT] = mot_cmd_set_joint_jerk_limit,
    [EMCMOT_UPDATE_JOINT_HOMING_PARAMS] = mot_cmd_update_joint_homing_params,
    [EMCMOT_SET_JOINT_MOTOR_OFFSET] = mot_cmd_set_joint_motor_offset,
    [EMCMOT_SET_JOINT_COMP] = mot_cmd_set_joint_comp,
    [EMCMOT_SET_AXIS_POSITION_LIMITS] = mot_cmd_set_axis_position_limits,
    [EMCMOT_SET_AXIS_VEL_LIMIT] = mot_cmd_set_axis_vel_limit,
    [EMCMOT_SET_AXIS_ACC_LIMIT] = mot_cmd_set_axis_acc_limit,
    [EMCMOT_SET_AXIS_LOCKING_JOINT] = mot_cmd_set_axis_locking_joint,
    [EMCMOT_SET_AXIS_JERK_LIMIT] = mot_cmd_set_axis_jerk_limit,
    [EMCMOT_SET_SPINDLE_PARAMS] = mot_cmd_set_spindle_params,
};

/* Reason of the command being handled ("" when accepted). */
static char reason[EMCMOT_REASON_LEN];
static int reason_reported;
static int handling;                            /* a command is being handled now */
static char first_report[EMCMOT_REASON_LEN];    /* first operator message it caused */

/* An operator message was queued; while a command runs, the first one is its likely reason. */
void mot_command_reported(const char *text)
{
    if (handling && !first_report[0])
        rtapi_snprintf(first_report, sizeof first_report, "%s", text);
}

/* Keep the reason, optionally queue it for the operator, return result. */
int mot_refuse(int result, int report, const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    rtapi_vsnprintf(reason, sizeof reason, fmt, ap);
    va_end(ap);
    if (report) {
        mot_report("%s", reason);
        reason_reported = 1;
    }
    return result;
}

/* Joint of cmd, or -1 after refusing. */
int mot_cmd_joint(const emcmot_command_t *cmd)
{
    if (cmd->joint < 0 || cmd->joint >= mot->num_joints) {
        mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "%s: joint %d is not 0..%d",
                   emcmot_command_name(cmd->command), cmd->joint, mot->num_joints - 1);
        return -1;
    }
    return cmd->joint;
}

/* Axis of cmd, or -1 after refusing. */
int mot_cmd_axis(const emcmot_command_t *cmd)
{
    if (cmd->axis < 0 || cmd->axis >= MOT_NUM_AXES) {
        mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "%s: axis %d is not 0..%d",
                   emcmot_command_name(cmd->command), cmd->axis, MOT_NUM_AXES - 1);
        return -1;
    }
    return cmd->axis;
}

/* Spindle of cmd, or -1 after refusing with text for the operator. */
int mot_cmd_spindle(const emcmot_command_t *cmd, const char *text)
{
    if (cmd->spindle < 0 || cmd->spindle >= mot->num_spindles) {
        mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "%s", text);
        return -1;
    }
    return cmd->spindle;
}

/* Commands that add a planner segment. */
int mot_cmd_is_move(int code)
{
    return code == EMCMOT_SET_LINE || code == EMCMOT_SET_CIRCLE || code == EMCMOT_PROBE ||
        code == EMCMOT_RIGID_TAP;
}

/* Commands whose success changes configuration readers may cache (status.config_serial). */
static int changes_config(int code)
{
    return (code >= EMCMOT_SET_VEL && code <= EMCMOT_SET_NUM_SPINDLES) ||
        code == EMCMOT_SET_WORLD_HOME || code == EMCMOT_SET_MAX_FEED_OVERRIDE ||
        code == EMCMOT_SETUP_ARC_BLENDS || code == EMCMOT_SET_PROBE_ERR_INHIBIT ||
        (code >= EMCMOT_SET_JOINT_POSITION_LIMITS && code <= EMCMOT_SET_SPINDLE_PARAMS);
}

/* Record a rejection in the echo's history. */
static void remember_rejection(const emcmot_command_t *cmd, int result)
{
    emcmot_echo_t *e = &mot->echo;
    emcmot_reject_t *r = &e->reject[e->reject_next % EMCMOT_REJECT_HISTORY];

    r->serial = cmd->serial;
    r->command = cmd->command;
    r->result = result;
    r->reported = reason_reported;
    memcpy(r->reason, reason, sizeof r->reason);
    e->reject_next = (e->reject_next + 1) % EMCMOT_REJECT_HISTORY;
    e->rejected++;
}

/* Check, dispatch and echo one command. */
static void handle_one(const emcmot_command_t *cmd)
{
    const char *field = "";
    int result;

    reason[0] = first_report[0] = '\0';
    reason_reported = 0;
    handling = 1;
    if (cmd->command < EMCMOT_FIRST_COMMAND || cmd->command > EMCMOT_LAST_COMMAND)
        result = mot_refuse(EMCMOT_COMMAND_UNKNOWN_COMMAND, 1, "unrecognized command %d",
                            cmd->command);
    else if (emcmot_command_check_finite(cmd, &field) < 0)
        result = mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "%s: %s is not a finite number",
                            emcmot_command_name(cmd->command), field);
    else
        result = handlers[cmd->command](cmd);
    handling = 0;
    if (result != EMCMOT_COMMAND_OK && !reason_reported && first_report[0]) {
        memcpy(reason, first_report, sizeof reason);
        reason_reported = 1;
    }
    mot->echo.serial = cmd->serial;
    mot->echo.command = cmd->command;
    mot->echo.result = result;
    mot->echo.handled++;
    if (result != EMCMOT_COMMAND_OK)
        remember_rejection(cmd, result);
    else if (changes_config(cmd->command))
        mot->status.config_serial++;
}

/* Non-zero when a move must wait in the ring: the planner has no room, or the moves it holds
   fill the shadow of their ids (units merge several moves into one planner entry, so this can
   come first). The status reports this as queue_full, so task never queues moves that would
   sit in the ring. */
int mot_planner_full(void)
{
    return mot->tp_ops->queue_full(mot->tp) ||
        mot->shadow_count >= MOT_TP_QUEUE_SIZE;
}

/* The servo function: handle queued commands in order, at most MOT_COMMAND_BUDGET. */
void mot_command_handler(void *arg, long period_ns)
{
    emcmot_command_t cmd;

    (void)arg;
    (void)period_ns;
    for (int n = 0; n < MOT_COMMAND_BUDGET; n++) {
        if (!emcmot_ring_peek(mot->shm, &cmd))
            break;
        if (mot_cmd_is_move(cmd.command) && mot_planner_full())
            break;
        emcmot_ring_pop(mot->shm);
        handle_one(&cmd);
    }
}
