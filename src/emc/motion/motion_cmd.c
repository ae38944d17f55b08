/* motion_cmd.c: names of the motion commands and the checks every command gets (realtime and user space). */
#include <errno.h>
#include <math.h>
#include <string.h>
#include "motion_cmd.h"

/* Command names in code order (index 0 is code 1), as motion-logger prints them. */
static const char *const command_names[] = {
    "ABORT", "ENABLE", "DISABLE", "PAUSE", "REVERSE", "FORWARD", "RESUME", "STEP", "FREE",
    "COORD", "TELEOP", "SPINDLE_SCALE", "SS_ENABLE", "FEED_SCALE", "RAPID_SCALE", "FS_ENABLE",
    "FH_ENABLE", "AF_ENABLE", "OVERRIDE_LIMITS", "SET_LINE", "SET_CIRCLE", "CLEAR_PROBE_FLAGS",
    "PROBE", "RIGID_TAP", "SET_VEL", "SET_VEL_LIMIT", "SET_ACC", "SET_JERK", "SET_PLANNER_TYPE",
    "SET_SCURVE_PEAK_SCALE", "SET_TERM_COND", "SET_NUM_JOINTS", "SET_NUM_SPINDLES",
    "SET_WORLD_HOME", "SET_DEBUG", "SET_DOUT", "SET_AOUT", "SET_SPINDLESYNC", "SPINDLE_ON",
    "SPINDLE_OFF", "SPINDLE_INCREASE", "SPINDLE_DECREASE", "SPINDLE_BRAKE_ENGAGE",
    "SPINDLE_BRAKE_RELEASE", "SPINDLE_ORIENT", "SET_OFFSET", "SET_MAX_FEED_OVERRIDE",
    "SETUP_ARC_BLENDS", "SET_PROBE_ERR_INHIBIT", "JOG_CONT", "JOG_INCR", "JOG_ABS", "JOG_ABORT",
    "JOINT_ACTIVATE", "JOINT_DEACTIVATE", "JOINT_HOME", "JOINT_UNHOME",
    "SET_JOINT_POSITION_LIMITS", "SET_JOINT_BACKLASH", "SET_JOINT_MIN_FERROR",
    "SET_JOINT_MAX_FERROR", "SET_JOINT_VEL_LIMIT", "SET_JOINT_ACC_LIMIT",
    "SET_JOINT_HOMING_PARAMS", "SET_JOINT_JERK_LIMIT", "UPDATE_JOINT_HOMING_PARAMS",
    "SET_JOINT_MOTOR_OFFSET", "SET_JOINT_COMP", "SET_AXIS_POSITION_LIMITS", "SET_AXIS_VEL_LIMIT",
    "SET_AXIS_ACC_LIMIT", "SET_AXIS_LOCKING_JOINT", "SET_AXIS_JERK_LIMIT", "SET_SPINDLE_PARAMS",
};

_Static_assert(sizeof command_names / sizeof command_names[0] ==
               EMCMOT_LAST_COMMAND - EMCMOT_FIRST_COMMAND + 1,
               "one name per command code");
_Static_assert(EMCMOT_SET_SPINDLE_PARAMS == 74, "LinuxCNC numbering");
_Static_assert(EMCMOT_JOG_CONT == 50, "LinuxCNC numbering");

/* Name of a command code, or NULL for an unknown code. */
const char *emcmot_command_name(int code)
{
    if (code < EMCMOT_FIRST_COMMAND || code > EMCMOT_LAST_COMMAND)
        return NULL;
    return command_names[code - EMCMOT_FIRST_COMMAND];
}

/* Name of a result code. */
const char *emcmot_result_name(int result)
{
    static const char *const names[] = {
        "OK", "UNKNOWN_COMMAND", "INVALID_COMMAND", "INVALID_PARAMS", "BAD_EXEC",
    };
    if (result < 0 || result > EMCMOT_COMMAND_BAD_EXEC)
        return "UNKNOWN_RESULT";
    return names[result];
}

/* Clear *cmd and set its code; "none" integers start at -1. */
void emcmot_command_init(emcmot_command_t *cmd, emcmot_command_code_t code)
{
    memset(cmd, 0, sizeof *cmd);
    cmd->command = code;
    cmd->joint = -1;
    cmd->axis = -1;
    cmd->spindle = 0;
    cmd->locking_joint = -1;
    cmd->turn = -1;
}

/* One floating-point member: where it starts, how many doubles, its name. */
typedef struct double_member {
    size_t offset;
    unsigned count;
    const char *name;
} double_member_t;

#define DM(field, n) { offsetof(emcmot_command_t, field), n, #field }
#define DE(field, name) { offsetof(emcmot_command_t, field), 1, name }
static const double_member_t double_members[] = {
    DE(pos.tran.x, "pos.x"), DE(pos.tran.y, "pos.y"), DE(pos.tran.z, "pos.z"),
    DE(pos.a, "pos.a"), DE(pos.b, "pos.b"), DE(pos.c, "pos.c"), DE(pos.u, "pos.u"),
    DE(pos.v, "pos.v"), DE(pos.w, "pos.w"), DE(center.x, "center.x"), DE(center.y, "center.y"),
    DE(center.z, "center.z"), DE(normal.x, "normal.x"), DE(normal.y, "normal.y"),
    DE(normal.z, "normal.z"), DM(vel, 1), DM(ini_maxvel, 1), DM(acc, 1),
    DM(jerk, 1), DM(tolerance, 1), DM(scale, 1), DM(offset, 1), DM(min_limit, 1),
    DM(max_limit, 1), DM(backlash, 1), DM(min_ferror, 1), DM(max_ferror, 1), DM(home, 1),
    DM(home_offset, 1), DM(home_final_vel, 1), DM(home_search_vel, 1), DM(home_latch_vel, 1),
    DM(comp_nominal, 1), DM(comp_forward, 1), DM(comp_reverse, 1), DM(spindle_sync, 1),
    DM(tap_pitch, 1), DM(speed, 1), DM(css_factor, 1), DM(css_xoffset, 1), DM(orientation, 1),
    DM(aout_start, 1), DM(aout_end, 1), DM(max_pos_speed, 1), DM(min_pos_speed, 1),
    DM(max_neg_speed, 1), DM(min_neg_speed, 1), DM(spindle_increment, 1),
    DM(ext_offset_vel, 1), DM(ext_offset_acc, 1), DM(arc_blend_gap_cycles, 1),
    DM(arc_blend_ramp_freq, 1), DM(arc_blend_tangent_kink_ratio, 1),
    DE(tag.settings[0], "tag.settings[0]"), DE(tag.settings[1], "tag.settings[1]"),
    DE(tag.settings[2], "tag.settings[2]"), DE(tag.settings[3], "tag.settings[3]"),
    DE(tag.settings[4], "tag.settings[4]"),
};
#undef DE
#undef DM

/* 0 when every floating-point member (the tag's settings included) is finite. */
int emcmot_command_check_finite(const emcmot_command_t *cmd, const char **field)
{
    const unsigned char *base = (const unsigned char *)cmd;
    size_t n = sizeof double_members / sizeof double_members[0];

    for (size_t m = 0; m < n; m++) {
        const double *value = (const double *)(base + double_members[m].offset);
        for (unsigned i = 0; i < double_members[m].count; i++) {
            if (!isfinite(value[i])) {
                if (field)
                    *field = double_members[m].name;
                return -EINVAL;
            }
        }
    }
    return 0;
}
