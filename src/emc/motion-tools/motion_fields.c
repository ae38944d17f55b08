/* motion_fields.c: name tables of emcmot_command_t and emcmot_status_t fields, with dotted paths and indexes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "motion_fields.h"

#define D(s, f) { #f, offsetof(s, f), MF_DOUBLE }
#define I(s, f) { #f, offsetof(s, f), MF_INT32 }
#define U(s, f) { #f, offsetof(s, f), MF_UINT32 }
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Sub-structures: a pose and a cartesian point. */
static const motion_field_t pose_fields[] = {
    { "x", offsetof(EmcPose, tran.x), MF_DOUBLE }, { "y", offsetof(EmcPose, tran.y), MF_DOUBLE },
    { "z", offsetof(EmcPose, tran.z), MF_DOUBLE }, { "a", offsetof(EmcPose, a), MF_DOUBLE },
    { "b", offsetof(EmcPose, b), MF_DOUBLE }, { "c", offsetof(EmcPose, c), MF_DOUBLE },
    { "u", offsetof(EmcPose, u), MF_DOUBLE }, { "v", offsetof(EmcPose, v), MF_DOUBLE },
    { "w", offsetof(EmcPose, w), MF_DOUBLE },
};
static const motion_field_t cart_fields[] = {
    { "x", offsetof(PmCartesian, x), MF_DOUBLE }, { "y", offsetof(PmCartesian, y), MF_DOUBLE },
    { "z", offsetof(PmCartesian, z), MF_DOUBLE },
};

#define C emcmot_command_t
static const motion_field_t command_fields[] = {
    D(C, vel), D(C, ini_maxvel), D(C, acc), D(C, jerk), D(C, tolerance), D(C, scale),
    D(C, offset), D(C, min_limit), D(C, max_limit), D(C, backlash), D(C, min_ferror),
    D(C, max_ferror), D(C, home), D(C, home_offset), D(C, home_final_vel), D(C, home_search_vel),
    D(C, home_latch_vel), D(C, comp_nominal), D(C, comp_forward), D(C, comp_reverse),
    D(C, spindle_sync), D(C, tap_pitch), D(C, speed), D(C, css_factor), D(C, css_xoffset),
    D(C, orientation), D(C, aout_start), D(C, aout_end), D(C, max_pos_speed), D(C, min_pos_speed),
    D(C, max_neg_speed), D(C, min_neg_speed), D(C, spindle_increment), D(C, ext_offset_vel),
    D(C, ext_offset_acc), D(C, arc_blend_gap_cycles), D(C, arc_blend_ramp_freq),
    D(C, arc_blend_tangent_kink_ratio),
    I(C, joint), I(C, axis), I(C, spindle), I(C, count), I(C, id), I(C, motion_type), I(C, turn),
    I(C, term_cond), I(C, probe_type), I(C, enable), I(C, planner_type), I(C, debug),
    I(C, io_index), I(C, now), I(C, dout_start), I(C, dout_end), I(C, sync_velocity_mode),
    I(C, wait_for_at_speed), I(C, orient_mode), I(C, home_flags), I(C, home_sequence),
    I(C, volatile_home), I(C, locking_joint), I(C, arc_blend_enable),
    I(C, arc_blend_fallback_enable), I(C, arc_blend_optimization_depth),
    I(C, probe_jog_err_inhibit), I(C, probe_home_err_inhibit), U(C, serial), I(C, command),
    { "tag.flags", offsetof(C, tag.flags), MF_UINT32 },
    { "tag.line_number", offsetof(C, tag.line_number), MF_INT32 },
};
#undef C

#define S emcmot_status_t
static const motion_field_t status_fields[] = {
    U(S, heartbeat), U(S, config_serial), D(S, cycle_time), I(S, joints), I(S, num_extra_joints),
    I(S, spindles), I(S, num_dio), I(S, num_aio), I(S, num_misc_error), I(S, kinematics_type),
    I(S, kinematics_switchable), I(S, kinematics_switch_type), I(S, planner_type), I(S, debug),
    D(S, vel), D(S, ini_maxvel), D(S, vel_limit), D(S, acc), D(S, jerk), D(S, max_feed_override),
    D(S, scurve_peak_scale), I(S, motion_state), I(S, enabled), I(S, coord), I(S, teleop),
    I(S, inpos), I(S, fault_code), I(S, homing_active), I(S, all_homed), I(S, on_soft_limit),
    I(S, jogging_active), I(S, paused), I(S, stepping), I(S, reverse),
    I(S, probe_err_inhibit_jog), I(S, probe_err_inhibit_home), I(S, queue_depth),
    I(S, active_depth), I(S, queue_full), I(S, queue_capacity), I(S, exec_id),
    I(S, motion_type), I(S, term_cond), D(S, tolerance), D(S, current_vel), D(S, requested_vel),
    D(S, distance_to_go), D(S, feed_scale), D(S, rapid_scale), D(S, net_feed_scale),
    I(S, feed_scale_enabled), I(S, feed_hold_enabled), I(S, adaptive_feed_enabled),
    I(S, spindle_sync_waiting), I(S, carte_pos_fb_ok), I(S, probing), I(S, probe_tripped),
    I(S, probe_val), I(S, probe_type), I(S, external_offsets_applied), I(S, eoffset_limited),
    { "echo.serial", offsetof(S, echo.serial), MF_UINT32 },
    { "echo.command", offsetof(S, echo.command), MF_INT32 },
    { "echo.result", offsetof(S, echo.result), MF_INT32 },
    { "echo.handled", offsetof(S, echo.handled), MF_UINT32 },
    { "echo.rejected", offsetof(S, echo.rejected), MF_UINT32 },
    { "exec_tag.line_number", offsetof(S, exec_tag.line_number), MF_INT32 },
};
static const struct { const char *name; size_t offset; } status_poses[] = {
    { "world_home", offsetof(S, world_home) }, { "tool_offset", offsetof(S, tool_offset) },
    { "dtg", offsetof(S, dtg) }, { "carte_pos_cmd", offsetof(S, carte_pos_cmd) },
    { "carte_pos_fb", offsetof(S, carte_pos_fb) }, { "probed_pos", offsetof(S, probed_pos) },
    { "eoffset_pose", offsetof(S, eoffset_pose) },
};
#undef S

#define JS emcmot_joint_status_t
static const motion_field_t joint_fields[] = {
    D(JS, pos_cmd), D(JS, pos_fb), D(JS, vel_cmd), D(JS, acc_cmd), D(JS, ferror),
    D(JS, ferror_high_mark), D(JS, ferror_limit), D(JS, min_ferror), D(JS, max_ferror),
    D(JS, min_pos_limit), D(JS, max_pos_limit), D(JS, vel_limit), D(JS, acc_limit),
    D(JS, jerk_limit), D(JS, backlash), D(JS, backlash_filt), D(JS, motor_offset),
    D(JS, home_offset), D(JS, home), I(JS, home_sequence), I(JS, home_state), I(JS, active),
    I(JS, enabled), I(JS, inpos), I(JS, homing), I(JS, homed), I(JS, error), I(JS, fault),
    I(JS, ferror_tripped), I(JS, min_soft_limit), I(JS, max_soft_limit), I(JS, min_hard_limit),
    I(JS, max_hard_limit), I(JS, override_limits), I(JS, jogging), I(JS, locking_indexer),
    I(JS, unlocked),
};
#undef JS
#define AS emcmot_axis_status_t
static const motion_field_t axis_fields[] = {
    D(AS, min_pos_limit), D(AS, max_pos_limit), D(AS, vel_limit), D(AS, acc_limit),
    D(AS, jerk_limit), D(AS, teleop_pos_cmd), D(AS, teleop_vel_cmd), D(AS, eoffset),
    D(AS, eoffset_request), I(AS, locking_joint), I(AS, teleop_jogging),
};
#undef AS
#define SS emcmot_spindle_status_t
static const motion_field_t spindle_fields[] = {
    D(SS, speed), D(SS, speed_out), D(SS, scale), D(SS, css_maximum), D(SS, css_factor),
    D(SS, css_xoffset), D(SS, speed_fb_rps), D(SS, revs), D(SS, orient_angle),
    D(SS, max_pos_speed), D(SS, min_pos_speed), D(SS, max_neg_speed), D(SS, min_neg_speed),
    D(SS, increment), I(SS, state), I(SS, direction), I(SS, brake), I(SS, increasing),
    I(SS, override_enabled), I(SS, orient_state), I(SS, orient_fault), I(SS, at_speed),
    I(SS, inhibit), I(SS, homed), I(SS, locked),
};
#undef SS

/* Field of a table by exact name. */
static const motion_field_t *lookup(const motion_field_t *t, size_t n, const char *name)
{
    for (size_t i = 0; i < n; i++)
        if (strcmp(t[i].name, name) == 0)
            return &t[i];
    return NULL;
}

/* name = prefix + '.' + rest?  Sets *rest. */
static int has_prefix(const char *name, const char *prefix, const char **rest)
{
    size_t n = strlen(prefix);

    if (strncmp(name, prefix, n) != 0 || name[n] != '.')
        return 0;
    *rest = name + n + 1;
    return 1;
}

/* "<index>.<field>" in one of count elements of size bytes. */
static int indexed(const char *rest, int count, size_t size, const motion_field_t *t, size_t n,
                   size_t base, motion_field_t *out)
{
    char *end;
    long i = strtol(rest, &end, 10);
    const motion_field_t *f;

    if (end == rest || *end != '.' || i < 0 || i >= count || !(f = lookup(t, n, end + 1)))
        return -1;
    *out = *f;
    out->offset += base + (size_t)i * size;
    return 0;
}

/* "<index>" of an array of count values. */
static int array_elem(const char *rest, int count, size_t size, motion_field_type_t type,
                      size_t base, motion_field_t *out)
{
    char *end;
    long i = strtol(rest, &end, 10);

    if (end == rest || *end || i < 0 || i >= count)
        return -1;
    *out = (motion_field_t){ rest, base + (size_t)i * size, type };
    return 0;
}

/* A named command field. */
int motion_command_field(const char *name, motion_field_t *out)
{
    const motion_field_t *f = lookup(command_fields, COUNT(command_fields), name);
    const char *rest;

    if (f) {
        *out = *f;
        return 0;
    }
    if (has_prefix(name, "pos", &rest) && (f = lookup(pose_fields, COUNT(pose_fields), rest))) {
        *out = *f;
        out->offset += offsetof(emcmot_command_t, pos);
        return 0;
    }
    if ((has_prefix(name, "center", &rest) || has_prefix(name, "normal", &rest)) &&
        (f = lookup(cart_fields, COUNT(cart_fields), rest))) {
        *out = *f;
        out->offset += name[0] == 'c' ? offsetof(emcmot_command_t, center)
                                      : offsetof(emcmot_command_t, normal);
        return 0;
    }
    if (has_prefix(name, "tag.gcodes", &rest))
        return array_elem(rest, STATE_TAG_GCODES, sizeof(int32_t), MF_INT32,
                          offsetof(emcmot_command_t, tag.gcodes), out);
    if (has_prefix(name, "tag.mcodes", &rest))
        return array_elem(rest, STATE_TAG_MCODES, sizeof(int32_t), MF_INT32,
                          offsetof(emcmot_command_t, tag.mcodes), out);
    if (has_prefix(name, "tag.settings", &rest))
        return array_elem(rest, STATE_TAG_SETTINGS, sizeof(double), MF_DOUBLE,
                          offsetof(emcmot_command_t, tag.settings), out);
    return -1;
}

/* Arrays of the status: I/O. */
static int status_array(const char *name, motion_field_t *out)
{
    const char *rest;

    if (has_prefix(name, "synch_di", &rest))
        return array_elem(rest, EMCMOT_MAX_DIO, 4, MF_INT32, offsetof(emcmot_status_t, synch_di), out);
    if (has_prefix(name, "synch_do", &rest))
        return array_elem(rest, EMCMOT_MAX_DIO, 4, MF_INT32, offsetof(emcmot_status_t, synch_do), out);
    if (has_prefix(name, "misc_error", &rest))
        return array_elem(rest, EMCMOT_MAX_MISC_ERROR, 4, MF_INT32,
                          offsetof(emcmot_status_t, misc_error), out);
    if (has_prefix(name, "analog_input", &rest))
        return array_elem(rest, EMCMOT_MAX_AIO, 8, MF_DOUBLE,
                          offsetof(emcmot_status_t, analog_input), out);
    if (has_prefix(name, "analog_output", &rest))
        return array_elem(rest, EMCMOT_MAX_AIO, 8, MF_DOUBLE,
                          offsetof(emcmot_status_t, analog_output), out);
    return -1;
}

/* A named status field. */
int motion_status_field(const char *name, motion_field_t *out)
{
    const motion_field_t *f = lookup(status_fields, COUNT(status_fields), name);
    const char *rest;

    if (f) {
        *out = *f;
        return 0;
    }
    for (size_t i = 0; i < COUNT(status_poses); i++) {
        if (has_prefix(name, status_poses[i].name, &rest) &&
            (f = lookup(pose_fields, COUNT(pose_fields), rest))) {
            *out = *f;
            out->offset += status_poses[i].offset;
            return 0;
        }
    }
    if (has_prefix(name, "joint", &rest))
        return indexed(rest, EMCMOT_MAX_JOINTS, sizeof(emcmot_joint_status_t), joint_fields,
                       COUNT(joint_fields), offsetof(emcmot_status_t, joint), out);
    if (has_prefix(name, "axis", &rest))
        return indexed(rest, EMCMOT_MAX_AXIS, sizeof(emcmot_axis_status_t), axis_fields,
                       COUNT(axis_fields), offsetof(emcmot_status_t, axis), out);
    if (has_prefix(name, "spindle", &rest))
        return indexed(rest, EMCMOT_MAX_SPINDLES, sizeof(emcmot_spindle_status_t),
                       spindle_fields, COUNT(spindle_fields), offsetof(emcmot_status_t, spindle),
                       out);
    return status_array(name, out);
}

/* Parse and store a value. */
int motion_field_set(void *base, const motion_field_t *f, const char *text)
{
    char *end;
    void *cell = (char *)base + f->offset;

    if (f->type == MF_DOUBLE) {
        double v = strtod(text, &end);
        if (end == text || *end)
            return -1;
        memcpy(cell, &v, sizeof v);
        return 0;
    }
    long long v = strtoll(text, &end, 0);
    if (end == text || *end)
        return -1;
    if (f->type == MF_INT32) {
        int32_t i = (int32_t)v;
        memcpy(cell, &i, sizeof i);
    } else {
        uint32_t u = (uint32_t)v;
        memcpy(cell, &u, sizeof u);
    }
    return 0;
}

/* Read a value as double. */
double motion_field_get(const void *base, const motion_field_t *f)
{
    const char *cell = (const char *)base + f->offset;
    double d;
    int32_t i;
    uint32_t u;

    switch (f->type) {
    case MF_DOUBLE:
        memcpy(&d, cell, sizeof d);
        return d;
    case MF_INT32:
        memcpy(&i, cell, sizeof i);
        return i;
    default:
        memcpy(&u, cell, sizeof u);
        return u;
    }
}
