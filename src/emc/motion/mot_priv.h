/* mot_priv.h: motmod's internal state: joints, axes, spindles, modes, pins and the links to kins/tp/homing. */
#ifndef MOT_PRIV_H
#define MOT_PRIV_H

#include <string.h>
#include "hal.h"
#include "kins_ops.h"
#include "tp_ops.h"
#include "home_ops.h"
#include "motion_shm.h"
#include "simple_tp.h"
#include "comp_table.h"
#include "cubic.h"

#define MOT_MAX_JOINTS EMCMOT_MAX_JOINTS
#define MOT_NUM_AXES EMCMOT_MAX_AXIS
#define MOT_MAX_SPINDLES EMCMOT_MAX_SPINDLES
#define MOT_MAX_DIO EMCMOT_MAX_DIO
#define MOT_MAX_AIO EMCMOT_MAX_AIO
#define MOT_MAX_MISC EMCMOT_MAX_MISC_ERROR
#define MOT_TP_QUEUE_SIZE 2000          /* planner segments (motion.md sec. 11) */
#define MOT_COMMAND_BUDGET 256          /* ring commands handled per servo cycle at most */

/* ---- HAL pins (allocated with hal_malloc: HAL writes the pointers) ---- */

typedef struct mot_joint_pins {
    hal_float_t *coarse_pos_cmd, *pos_cmd, *pos_fb, *motor_pos_cmd, *motor_offset, *vel_cmd,
        *acc_cmd, *jerk_cmd, *backlash_corr, *backlash_filt, *backlash_vel, *f_error,
        *f_error_lim, *free_pos_cmd, *free_vel_lim;
    hal_bit_t *amp_enable_out, *free_tp_enable, *kb_jog_active, *wheel_jog_active,
        *in_position, *pos_hard_limit, *neg_hard_limit, *active, *error, *f_errored, *faulted;
    hal_float_t *motor_pos_fb, *jog_scale, *jog_accel_fraction;
    hal_bit_t *pos_lim_sw_in, *neg_lim_sw_in, *amp_fault_in, *jog_enable, *jog_vel_mode;
    hal_s32_t *jog_counts;
    hal_bit_t *unlock, *is_unlocked;    /* only for joints in unlock_joints_mask */
    hal_float_t *posthome_cmd;          /* only for extra joints */
} mot_joint_pins_t;

typedef struct mot_axis_pins {
    hal_bit_t *jog_enable, *jog_vel_mode, *eoffset_enable, *eoffset_clear;
    hal_float_t *jog_scale, *jog_accel_fraction, *eoffset_scale;
    hal_s32_t *jog_counts, *eoffset_counts;
    hal_bit_t *kb_jog_active, *wheel_jog_active, *teleop_tp_enable;
    hal_float_t *pos_cmd, *teleop_pos_cmd, *teleop_vel_cmd, *teleop_vel_lim, *eoffset,
        *eoffset_request;
} mot_axis_pins_t;

typedef struct mot_spindle_pins {
    hal_bit_t *on, *forward, *reverse, *brake, *orient, *locked;
    hal_float_t *speed_out, *speed_out_abs, *speed_out_rps, *speed_out_rps_abs, *speed_cmd_rps,
        *orient_angle;
    hal_s32_t *orient_mode, *orient_fault;
    hal_bit_t *inhibit, *amp_fault_in, *is_oriented, *at_speed, *index_enable;
    hal_float_t *revs, *speed_in;
} mot_spindle_pins_t;

typedef struct mot_pins {
    hal_bit_t *probe_input, *feed_hold, *feed_inhibit, *homing_inhibit, *jog_inhibit, *jog_stop,
        *jog_stop_immediate, *enable;
    hal_float_t *adaptive_feed, *switchkins_type;
    hal_bit_t *tp_reverse, *is_all_homed, *motion_enabled, *in_position, *coord_mode,
        *teleop_mode, *coord_error, *on_soft_limit, *jog_is_active, *interp_iscircle,
        *eoffset_limited, *eoffset_active;
    hal_float_t *feed_upm, *feed_inches_per_minute, *feed_inches_per_second,
        *feed_mm_per_minute, *feed_mm_per_second, *current_vel, *requested_vel,
        *distance_to_go, *interp_feedrate, *interp_arc_radius, *interp_arc_center_x,
        *interp_arc_center_y, *interp_arc_center_z, *interp_heading, *interp_normal_heading;
    hal_float_t *tooloffset[MOT_NUM_AXES];
    hal_s32_t *motion_type, *program_line, *interp_line_number, *interp_motion_type;
    hal_u32_t *servo_last_period;
    hal_bit_t *digital_in[MOT_MAX_DIO], *digital_out[MOT_MAX_DIO], *misc_error[MOT_MAX_MISC];
    hal_float_t *analog_in[MOT_MAX_AIO], *analog_out[MOT_MAX_AIO];
    /* parameters (RO) */
    hal_bit_t debug_bit[2];
    hal_float_t debug_float[4];
    hal_s32_t debug_s32[2];
    hal_float_t traj_pos_out, traj_vel_out;
    hal_u32_t traj_active_tc;
    hal_float_t tc_pos[4], tc_vel[4], tc_acc[4];
    mot_joint_pins_t joint[MOT_MAX_JOINTS];
    mot_axis_pins_t axis[MOT_NUM_AXES];
    mot_spindle_pins_t spindle[MOT_MAX_SPINDLES];
} mot_pins_t;

/* ---- joints, axes, spindles ---- */

typedef struct mot_joint {
    /* configuration (SET_JOINT_*) */
    double min_limit, max_limit;
    double vel_limit, acc_limit, jerk_limit;
    double backlash, min_ferror, max_ferror, motor_offset;
    comp_table_t comp;
    int active;                 /* JOINT_ACTIVATE */
    int locking_indexer;        /* home_flags UNLOCK_FIRST */
    /* servo state */
    double pos_cmd, coarse_pos, vel_cmd, acc_cmd, jerk_cmd;
    double pos_fb, motor_pos_fb, motor_pos_cmd;
    double ferror, ferror_limit, ferror_high_mark;
    double backlash_corr, backlash_filt, backlash_vel;
    simple_tp_t free_tp;
    simple_tp_t backlash_tp;    /* ramps backlash_filt toward backlash_corr */
    int comp_dir;               /* last commanded direction: 1, -1, 0 not moved yet */
    double wheel_accel_fraction;
    cubic_t cubic;
    int free_tp_enable;
    /* flags */
    int enabled, inpos, error, ferror_tripped, faulted, amp_fault;
    int pos_hard, neg_hard;     /* switches this cycle */
    int pos_soft, neg_soft;     /* commanded position at a soft limit */
    int override_mask;          /* 1: switches tripped at OVERRIDE_LIMITS are ignored */
    int kb_jog_active, wheel_jog_active;
    int jog_counts_old;
    int jog_counts_valid;
} mot_joint_t;

typedef struct mot_axis {
    double min_limit, max_limit;
    double vel_limit, acc_limit, jerk_limit;
    double ext_offset_vel, ext_offset_acc;
    int locking_joint;
    simple_tp_t teleop_tp;
    simple_tp_t ext_offset_tp;
    int kb_jog_active, wheel_jog_active;
    int jog_counts_old, jog_counts_valid;
    int eoffset_counts_old, eoffset_counts_valid;
    double pos_cmd;             /* axis position including external offset */
    double eoffset_raw;         /* external offset asked for: counts x scale */
    double eoffset_request;     /* the same kept inside the axis limits */
} mot_axis_t;

typedef struct mot_spindle {
    double speed;               /* commanded rpm, signed (CSS: surface speed) */
    double css_factor, css_xoffset;
    double scale;               /* override */
    double net_scale;
    double speed_out;           /* after override, CSS and limits */
    double max_pos_speed, min_pos_speed, max_neg_speed, min_neg_speed, increment;
    int on, direction, brake, increasing;
    int override_enabled;
    int orient_state, orient_mode;
    double orient_angle;
    int orient_fault;
    int locked;
    int at_speed, inhibit;
    int tap_reverse;            /* rigid tap asks for the opposite direction */
    double revs, speed_fb_rps;
} mot_spindle_t;

/* A queued segment as motion remembers it (for the interp.* arc pins). */
typedef struct mot_shadow_seg {
    int32_t id;
    int is_circle;
    int clockwise;
    PmCartesian center;
    double radius;
} mot_shadow_seg_t;

/* ---- the whole controller ---- */

typedef struct mot {
    /* module configuration */
    int comp_id;
    int max_joints;             /* num_joints module parameter: pins exist for these */
    int num_joints;             /* SET_NUM_JOINTS (<= max_joints) */
    int num_extra_joints;
    int num_kins_joints;        /* joints that feed kinematics */
    int max_spindles;           /* num_spindles module parameter */
    int num_spindles;           /* SET_NUM_SPINDLES */
    int num_dio, num_aio, num_misc_error;
    unsigned unlock_joints_mask;
    double servo_period;        /* s */
    double traj_period;         /* s */
    int interp_rate;            /* servo cycles per trajectory cycle */
    int interp_count;

    /* links */
    const kins_ops_t *kins;
    const tp_ops_t *tp_ops;
    tp_planner_t *tp;
    const home_ops_t *home;
    home_joint_t home_joints[MOT_MAX_JOINTS];   /* shared with the homing module */
    emcmot_shm_t *shm;
    int shm_id;

    /* configuration commands */
    tp_limits_t tp_limits;
    double vel, ini_maxvel, vel_limit, acc, jerk, max_feed_override, scurve_peak_scale;
    int planner_type, planner_type_pending, term_cond;
    double tolerance;
    EmcPose world_home, tool_offset;
    int debug;
    int probe_err_inhibit_jog, probe_err_inhibit_home;

    /* mode and state */
    int enabling;               /* ENABLE requested */
    int enabled;
    int want_coord, want_teleop;
    int coord, teleop;          /* mode in force */
    int motion_state;           /* emcmot_motion_state_t */
    int fault_code;
    int paused, stepping, step_id, reverse;
    int inpos;
    int on_soft_limit;
    int kins_switch_type;
    int kins_switch_refused;    /* last switchkins-type the kinematics refused */
    int kins_ok;                /* forward kinematics usable for feedback */
    int all_homed;

    /* feeds and overrides */
    double feed_scale, rapid_scale, net_feed_scale;
    int fs_enabled, fh_enabled, af_enabled;
    int atspeed_next_feed;
    int spindle_sync_spindle;
    double spindle_sync;
    int spindle_sync_velocity;

    /* positions */
    EmcPose carte_pos_cmd, carte_pos_fb, carte_pos_fb_old;
    EmcPose coord_pos;          /* planner output before external offsets */
    int carte_pos_fb_ok;
    double current_vel, requested_vel, distance_to_go;
    EmcPose dtg;
    EmcPose queued_end;         /* end of the last queued segment */
    int indexer_joint;          /* locking indexer joint the planner asked to unlock, -1 */
    int reverse_running;        /* the planner runs backwards now */
    int exec_id, motion_type, queue_depth, active_depth, queue_full, spindle_sync_waiting;
    state_tag_t exec_tag;
    double heading, normal_heading;

    /* probing */
    int probing, probe_type, probe_tripped, probe_val, probe_id;
    EmcPose probed_pos;

    /* external offsets */
    int eoffset_active, eoffset_limited;

    /* I/O */
    int dout[MOT_MAX_DIO];
    double aout[MOT_MAX_AIO];

    /* joints, axes, spindles */
    mot_joint_t joint[MOT_MAX_JOINTS];
    mot_axis_t axis[MOT_NUM_AXES];
    mot_spindle_t spindle[MOT_MAX_SPINDLES];

    /* shadow of queued segments for interp.* pins */
    mot_shadow_seg_t shadow[MOT_TP_QUEUE_SIZE];
    int shadow_head, shadow_count;

    /* timing */
    long long last_cycle_ns;
    uint32_t heartbeat;

    /* command echo and published status (built here, then copied out) */
    emcmot_echo_t echo;
    emcmot_status_t status;

    mot_pins_t *pins;
} mot_t;

extern mot_t *mot;

/* ---- mot_report.c ---- */
/* Queue an operator message (no printing in the cycle). */
void mot_report(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* ---- mot_command.c ---- */
/* Tell the command handler an operator message was queued (a refusal's reason). */
void mot_command_reported(const char *text);

/* ---- mot_pins.c ---- */
struct mot_config;
int mot_pins_create(const struct mot_config *cfg);

/* ---- mot_command.c ---- */
void mot_command_handler(void *arg, long period_ns);
/* No room for another move (the planner's queue or the shadow of move ids is full). */
int mot_planner_full(void);

/* ---- mot_control.c ---- */
void mot_controller(void *arg, long period_ns);

/* helpers used across files */
double mot_pose_get(const EmcPose *pose, int axis);
void mot_pose_set(EmcPose *pose, int axis, double value);
int mot_joints_homed(void);
int mot_kins_homing_required(void);
void mot_set_state_disabled(void);
void mot_abort_jogs(void);
void mot_clear_planner(void);
int mot_inverse_kins(const EmcPose *pos, double *joints);
void mot_forward_kins_cmd(void);
void mot_sync_free_to_cmd(void);
void mot_sync_teleop_to_cmd(void);
int mot_any_joint_moving(void);

#endif
