/* mot_pins.c: motmod's HAL pins and parameters, made from tables (motion.md sec. 5). */
#include <stdio.h>
#include "rtapi.h"
#include "mot_priv.h"
#include "mot_params.h"

/* One pin: name after the prefix, type, direction, where its pointer lives. */
typedef struct pin_def {
    const char *name;
    hal_type_t type;
    hal_pin_dir_t dir;
    size_t offset;
} pin_def_t;

#define MP(n, t, d, f) { n, t, d, offsetof(mot_pins_t, f) }
static const pin_def_t motion_pins[] = {
    MP("probe-input", HAL_BIT, HAL_IN, probe_input), MP("feed-hold", HAL_BIT, HAL_IN, feed_hold),
    MP("feed-inhibit", HAL_BIT, HAL_IN, feed_inhibit),
    MP("homing-inhibit", HAL_BIT, HAL_IN, homing_inhibit),
    MP("jog-inhibit", HAL_BIT, HAL_IN, jog_inhibit), MP("jog-stop", HAL_BIT, HAL_IN, jog_stop),
    MP("jog-stop-immediate", HAL_BIT, HAL_IN, jog_stop_immediate),
    MP("enable", HAL_BIT, HAL_IN, enable), MP("adaptive-feed", HAL_FLOAT, HAL_IN, adaptive_feed),
    MP("tp-reverse", HAL_BIT, HAL_OUT, tp_reverse),
    MP("is-all-homed", HAL_BIT, HAL_OUT, is_all_homed),
    MP("motion-enabled", HAL_BIT, HAL_OUT, motion_enabled),
    MP("in-position", HAL_BIT, HAL_OUT, in_position),
    MP("coord-mode", HAL_BIT, HAL_OUT, coord_mode), MP("teleop-mode", HAL_BIT, HAL_OUT, teleop_mode),
    MP("coord-error", HAL_BIT, HAL_OUT, coord_error),
    MP("on-soft-limit", HAL_BIT, HAL_OUT, on_soft_limit),
    MP("jog-is-active", HAL_BIT, HAL_OUT, jog_is_active),
    MP("interp.iscircle", HAL_BIT, HAL_OUT, interp_iscircle),
    MP("eoffset-limited", HAL_BIT, HAL_OUT, eoffset_limited),
    MP("eoffset-active", HAL_BIT, HAL_OUT, eoffset_active),
    MP("feed-upm", HAL_FLOAT, HAL_OUT, feed_upm),
    MP("feed-inches-per-minute", HAL_FLOAT, HAL_OUT, feed_inches_per_minute),
    MP("feed-inches-per-second", HAL_FLOAT, HAL_OUT, feed_inches_per_second),
    MP("feed-mm-per-minute", HAL_FLOAT, HAL_OUT, feed_mm_per_minute),
    MP("feed-mm-per-second", HAL_FLOAT, HAL_OUT, feed_mm_per_second),
    MP("current-vel", HAL_FLOAT, HAL_OUT, current_vel),
    MP("requested-vel", HAL_FLOAT, HAL_OUT, requested_vel),
    MP("distance-to-go", HAL_FLOAT, HAL_OUT, distance_to_go),
    MP("interp.feedrate", HAL_FLOAT, HAL_OUT, interp_feedrate),
    MP("interp.arc-radius", HAL_FLOAT, HAL_OUT, interp_arc_radius),
    MP("interp.arc-center-x", HAL_FLOAT, HAL_OUT, interp_arc_center_x),
    MP("interp.arc-center-y", HAL_FLOAT, HAL_OUT, interp_arc_center_y),
    MP("interp.arc-center-z", HAL_FLOAT, HAL_OUT, interp_arc_center_z),
    MP("interp.heading", HAL_FLOAT, HAL_OUT, interp_heading),
    MP("interp.normal-heading", HAL_FLOAT, HAL_OUT, interp_normal_heading),
    MP("motion-type", HAL_S32, HAL_OUT, motion_type),
    MP("program-line", HAL_S32, HAL_OUT, program_line),
    MP("interp.line-number", HAL_S32, HAL_OUT, interp_line_number),
    MP("interp.motion-type", HAL_S32, HAL_OUT, interp_motion_type),
    MP("servo.last-period", HAL_U32, HAL_OUT, servo_last_period),
};
#undef MP

#define JP(n, t, d, f) { n, t, d, offsetof(mot_joint_pins_t, f) }
static const pin_def_t joint_pins[] = {
    JP("coarse-pos-cmd", HAL_FLOAT, HAL_OUT, coarse_pos_cmd), JP("pos-cmd", HAL_FLOAT, HAL_OUT, pos_cmd),
    JP("pos-fb", HAL_FLOAT, HAL_OUT, pos_fb), JP("motor-pos-cmd", HAL_FLOAT, HAL_OUT, motor_pos_cmd),
    JP("motor-offset", HAL_FLOAT, HAL_OUT, motor_offset), JP("vel-cmd", HAL_FLOAT, HAL_OUT, vel_cmd),
    JP("acc-cmd", HAL_FLOAT, HAL_OUT, acc_cmd), JP("jerk-cmd", HAL_FLOAT, HAL_OUT, jerk_cmd),
    JP("backlash-corr", HAL_FLOAT, HAL_OUT, backlash_corr),
    JP("backlash-filt", HAL_FLOAT, HAL_OUT, backlash_filt),
    JP("backlash-vel", HAL_FLOAT, HAL_OUT, backlash_vel), JP("f-error", HAL_FLOAT, HAL_OUT, f_error),
    JP("f-error-lim", HAL_FLOAT, HAL_OUT, f_error_lim),
    JP("free-pos-cmd", HAL_FLOAT, HAL_OUT, free_pos_cmd),
    JP("free-vel-lim", HAL_FLOAT, HAL_OUT, free_vel_lim),
    JP("amp-enable-out", HAL_BIT, HAL_OUT, amp_enable_out),
    JP("free-tp-enable", HAL_BIT, HAL_OUT, free_tp_enable),
    JP("kb-jog-active", HAL_BIT, HAL_OUT, kb_jog_active),
    JP("wheel-jog-active", HAL_BIT, HAL_OUT, wheel_jog_active),
    JP("in-position", HAL_BIT, HAL_OUT, in_position),
    JP("pos-hard-limit", HAL_BIT, HAL_OUT, pos_hard_limit),
    JP("neg-hard-limit", HAL_BIT, HAL_OUT, neg_hard_limit), JP("active", HAL_BIT, HAL_OUT, active),
    JP("error", HAL_BIT, HAL_OUT, error), JP("f-errored", HAL_BIT, HAL_OUT, f_errored),
    JP("faulted", HAL_BIT, HAL_OUT, faulted),
    JP("motor-pos-fb", HAL_FLOAT, HAL_IN, motor_pos_fb),
    JP("pos-lim-sw-in", HAL_BIT, HAL_IN, pos_lim_sw_in),
    JP("neg-lim-sw-in", HAL_BIT, HAL_IN, neg_lim_sw_in),
    JP("amp-fault-in", HAL_BIT, HAL_IN, amp_fault_in), JP("jog-enable", HAL_BIT, HAL_IN, jog_enable),
    JP("jog-vel-mode", HAL_BIT, HAL_IN, jog_vel_mode), JP("jog-counts", HAL_S32, HAL_IN, jog_counts),
    JP("jog-scale", HAL_FLOAT, HAL_IN, jog_scale),
    JP("jog-accel-fraction", HAL_FLOAT, HAL_IN, jog_accel_fraction),
};
static const pin_def_t joint_unlock_pins[] = {
    JP("unlock", HAL_BIT, HAL_OUT, unlock), JP("is-unlocked", HAL_BIT, HAL_IN, is_unlocked),
};
static const pin_def_t joint_extra_pins[] = {
    JP("posthome-cmd", HAL_FLOAT, HAL_IN, posthome_cmd),
};
#undef JP

#define AP(n, t, d, f) { n, t, d, offsetof(mot_axis_pins_t, f) }
static const pin_def_t axis_pins[] = {
    AP("jog-enable", HAL_BIT, HAL_IN, jog_enable), AP("jog-scale", HAL_FLOAT, HAL_IN, jog_scale),
    AP("jog-counts", HAL_S32, HAL_IN, jog_counts), AP("jog-vel-mode", HAL_BIT, HAL_IN, jog_vel_mode),
    AP("jog-accel-fraction", HAL_FLOAT, HAL_IN, jog_accel_fraction),
    AP("eoffset-enable", HAL_BIT, HAL_IN, eoffset_enable),
    AP("eoffset-clear", HAL_BIT, HAL_IN, eoffset_clear),
    AP("eoffset-counts", HAL_S32, HAL_IN, eoffset_counts),
    AP("eoffset-scale", HAL_FLOAT, HAL_IN, eoffset_scale),
    AP("kb-jog-active", HAL_BIT, HAL_OUT, kb_jog_active),
    AP("wheel-jog-active", HAL_BIT, HAL_OUT, wheel_jog_active),
    AP("teleop-tp-enable", HAL_BIT, HAL_OUT, teleop_tp_enable),
    AP("pos-cmd", HAL_FLOAT, HAL_OUT, pos_cmd),
    AP("teleop-pos-cmd", HAL_FLOAT, HAL_OUT, teleop_pos_cmd),
    AP("teleop-vel-cmd", HAL_FLOAT, HAL_OUT, teleop_vel_cmd),
    AP("teleop-vel-lim", HAL_FLOAT, HAL_OUT, teleop_vel_lim),
    AP("eoffset", HAL_FLOAT, HAL_OUT, eoffset),
    AP("eoffset-request", HAL_FLOAT, HAL_OUT, eoffset_request),
};
#undef AP

#define SP(n, t, d, f) { n, t, d, offsetof(mot_spindle_pins_t, f) }
static const pin_def_t spindle_pins[] = {
    SP("on", HAL_BIT, HAL_OUT, on), SP("forward", HAL_BIT, HAL_OUT, forward),
    SP("reverse", HAL_BIT, HAL_OUT, reverse), SP("brake", HAL_BIT, HAL_OUT, brake),
    SP("orient", HAL_BIT, HAL_OUT, orient), SP("locked", HAL_BIT, HAL_OUT, locked),
    SP("speed-out", HAL_FLOAT, HAL_OUT, speed_out),
    SP("speed-out-abs", HAL_FLOAT, HAL_OUT, speed_out_abs),
    SP("speed-out-rps", HAL_FLOAT, HAL_OUT, speed_out_rps),
    SP("speed-out-rps-abs", HAL_FLOAT, HAL_OUT, speed_out_rps_abs),
    SP("speed-cmd-rps", HAL_FLOAT, HAL_OUT, speed_cmd_rps),
    SP("orient-angle", HAL_FLOAT, HAL_OUT, orient_angle),
    SP("orient-mode", HAL_S32, HAL_OUT, orient_mode), SP("inhibit", HAL_BIT, HAL_IN, inhibit),
    SP("amp-fault-in", HAL_BIT, HAL_IN, amp_fault_in),
    SP("is-oriented", HAL_BIT, HAL_IN, is_oriented), SP("at-speed", HAL_BIT, HAL_IN, at_speed),
    SP("orient-fault", HAL_S32, HAL_IN, orient_fault), SP("revs", HAL_FLOAT, HAL_IN, revs),
    SP("speed-in", HAL_FLOAT, HAL_IN, speed_in), SP("index-enable", HAL_BIT, HAL_IO, index_enable),
};
#undef SP

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* Create each pin of defs as <prefix>.<name>, pointers stored at base + offset. */
static int make_pins(const char *prefix, const pin_def_t *defs, int n, void *base)
{
    char name[HAL_NAME_LEN + 1];

    for (int i = 0; i < n; i++) {
        snprintf(name, sizeof name, "%s.%s", prefix, defs[i].name);
        int rc = hal_pin_new(name, defs[i].type, defs[i].dir,
                             (void **)((char *)base + defs[i].offset), mot->comp_id);
        if (rc < 0)
            return rc;
    }
    return 0;
}

/* Pins of one joint; unlock pins for masked joints, posthome-cmd for extra joints. */
static int make_joint_pins(int j)
{
    mot_joint_pins_t *p = &mot->pins->joint[j];
    char prefix[32];
    int rc;

    snprintf(prefix, sizeof prefix, "joint.%d", j);
    rc = make_pins(prefix, joint_pins, COUNT(joint_pins), p);
    if (rc == 0 && (mot->unlock_joints_mask & (1u << j)))
        rc = make_pins(prefix, joint_unlock_pins, COUNT(joint_unlock_pins), p);
    if (rc == 0 && j >= mot->max_joints - mot->num_extra_joints)
        rc = make_pins(prefix, joint_extra_pins, COUNT(joint_extra_pins), p);
    if (rc == 0)
        *p->jog_accel_fraction = 1.0;
    return rc;
}

/* One numbered-or-named I/O family: named slots first, the rest numbered from 00. */
static int make_io_pins(int count, const mot_names_t *names, const char *named_fmt,
                        const char *numbered_fmt, hal_type_t type, hal_pin_dir_t dir, void **cells,
                        size_t cell_size)
{
    char name[HAL_NAME_LEN + 1];

    for (int i = 0; i < count; i++) {
        if (i < names->count)
            snprintf(name, sizeof name, named_fmt, names->name[i]);
        else
            snprintf(name, sizeof name, numbered_fmt, i - names->count);
        int rc = hal_pin_new(name, type, dir, (void **)((char *)cells + i * cell_size),
                             mot->comp_id);
        if (rc < 0)
            return rc;
    }
    return 0;
}

/* Digital, analog and misc-error pins. */
static int make_all_io_pins(const mot_config_t *cfg)
{
    mot_pins_t *p = mot->pins;
    int rc = make_io_pins(cfg->num_dio, &cfg->din, "motion.din-%s", "motion.digital-in-%02d",
                          HAL_BIT, HAL_IN, (void **)p->digital_in, sizeof p->digital_in[0]);
    if (rc == 0)
        rc = make_io_pins(cfg->num_dio, &cfg->dout, "motion.dout-%s", "motion.digital-out-%02d",
                          HAL_BIT, HAL_OUT, (void **)p->digital_out, sizeof p->digital_out[0]);
    if (rc == 0)
        rc = make_io_pins(cfg->num_aio, &cfg->ain, "motion.ain-%s", "motion.analog-in-%02d",
                          HAL_FLOAT, HAL_IN, (void **)p->analog_in, sizeof p->analog_in[0]);
    if (rc == 0)
        rc = make_io_pins(cfg->num_aio, &cfg->aout, "motion.aout-%s", "motion.analog-out-%02d",
                          HAL_FLOAT, HAL_OUT, (void **)p->analog_out, sizeof p->analog_out[0]);
    if (rc == 0)
        rc = make_io_pins(cfg->num_misc_error, &cfg->misc, "motion.err-%s", "motion.misc-error-%02d",
                          HAL_BIT, HAL_IN, (void **)p->misc_error, sizeof p->misc_error[0]);
    return rc;
}

/* The read-only debug parameters LinuxCNC configurations may reference. */
static int make_params(void)
{
    mot_pins_t *p = mot->pins;
    int rc = 0, id = mot->comp_id;

    for (int i = 0; i < 2 && rc == 0; i++)
        rc = hal_param_bit_newf(HAL_RO, &p->debug_bit[i], id, "motion.debug-bit-%d", i);
    for (int i = 0; i < 4 && rc == 0; i++)
        rc = hal_param_float_newf(HAL_RO, &p->debug_float[i], id, "motion.debug-float-%d", i);
    for (int i = 0; i < 2 && rc == 0; i++)
        rc = hal_param_s32_newf(HAL_RO, &p->debug_s32[i], id, "motion.debug-s32-%d", i);
    if (rc == 0)
        rc = hal_param_float_newf(HAL_RO, &p->traj_pos_out, id, "traj.pos_out");
    if (rc == 0)
        rc = hal_param_float_newf(HAL_RO, &p->traj_vel_out, id, "traj.vel_out");
    if (rc == 0)
        rc = hal_param_u32_newf(HAL_RO, &p->traj_active_tc, id, "traj.active_tc");
    for (int i = 0; i < 4 && rc == 0; i++) {
        rc = hal_param_float_newf(HAL_RO, &p->tc_pos[i], id, "tc.%d.pos", i);
        if (rc == 0)
            rc = hal_param_float_newf(HAL_RO, &p->tc_vel[i], id, "tc.%d.vel", i);
        if (rc == 0)
            rc = hal_param_float_newf(HAL_RO, &p->tc_acc[i], id, "tc.%d.acc", i);
    }
    return rc;
}

/* motion.* pins with their defaults, tool offsets and the optional switchkins-type. */
static int make_motion_pins(void)
{
    static const char letters[] = "xyzabcuvw";
    mot_pins_t *p = mot->pins;
    int rc = make_pins("motion", motion_pins, COUNT(motion_pins), p);

    for (int i = 0; i < MOT_NUM_AXES && rc == 0; i++)
        rc = hal_pin_float_newf(HAL_OUT, &p->tooloffset[i], mot->comp_id, "motion.tooloffset.%c",
                                letters[i]);
    if (rc == 0 && mot->kins->switchable())
        rc = hal_pin_float_newf(HAL_IN, &p->switchkins_type, mot->comp_id,
                                "motion.switchkins-type");
    if (rc < 0)
        return rc;
    *p->enable = 1;
    *p->adaptive_feed = 1.0;
    return 0;
}

/* Every pin and parameter of motmod. */
int mot_pins_create(const mot_config_t *cfg)
{
    static const char letters[] = "xyzabcuvw";
    char prefix[32];
    int rc;

    mot->pins = hal_malloc(sizeof(mot_pins_t));
    if (!mot->pins)
        return -ENOMEM;
    memset(mot->pins, 0, sizeof(mot_pins_t));
    rc = make_motion_pins();
    if (rc == 0)
        rc = make_all_io_pins(cfg);
    for (int j = 0; j < mot->max_joints && rc == 0; j++)
        rc = make_joint_pins(j);
    for (int a = 0; a < MOT_NUM_AXES && rc == 0; a++) {
        snprintf(prefix, sizeof prefix, "axis.%c", letters[a]);
        rc = make_pins(prefix, axis_pins, COUNT(axis_pins), &mot->pins->axis[a]);
        if (rc == 0)
            *mot->pins->axis[a].jog_accel_fraction = 1.0;
    }
    for (int s = 0; s < mot->max_spindles && rc == 0; s++) {
        snprintf(prefix, sizeof prefix, "spindle.%d", s);
        rc = make_pins(prefix, spindle_pins, COUNT(spindle_pins), &mot->pins->spindle[s]);
        if (rc == 0)
            *mot->pins->spindle[s].at_speed = 1;
    }
    if (rc == 0)
        rc = make_params();
    if (rc < 0)
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: cannot create the HAL pins (%d)\n", rc);
    return rc;
}
