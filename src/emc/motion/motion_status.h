/* motion_status.h: the status snapshot motion publishes each servo cycle (what task copies into EMC_STAT). */
#ifndef MOTION_STATUS_H
#define MOTION_STATUS_H

#include <stdint.h>
#include "emcpos.h"
#include "state_tag.h"
#include "motion_cmd.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Motion state (LinuxCNC's EMCMOT_MOTION_*); task maps FREE/TELEOP/COORD to EMC_TRAJ_MODE. */
typedef enum emcmot_motion_state {
    EMCMOT_MOTION_DISABLED = 0,
    EMCMOT_MOTION_FREE = 1,
    EMCMOT_MOTION_TELEOP = 2,
    EMCMOT_MOTION_COORD = 3
} emcmot_motion_state_t;

/* Why motion disabled itself (status.fault_code); 0 = no fault since the last ENABLE. */
typedef enum emcmot_fault {
    EMCMOT_FAULT_NONE = 0,
    EMCMOT_FAULT_HARD_LIMIT,        /* joint on limit switch */
    EMCMOT_FAULT_AMP,               /* joint amplifier fault */
    EMCMOT_FAULT_FERROR,            /* following error */
    EMCMOT_FAULT_SPINDLE_AMP,       /* spindle amplifier fault */
    EMCMOT_FAULT_MISC_ERROR,        /* motion.misc-error-NN */
    EMCMOT_FAULT_ENABLE_INPUT,      /* motion.enable went false */
    EMCMOT_FAULT_KINEMATICS         /* inverse kinematics failed or gave non-finite joints */
} emcmot_fault_t;

/* One rejected command (the echo keeps the last few so none is missed). */
#define EMCMOT_REASON_LEN 256
typedef struct emcmot_reject {
    uint32_t serial;            /* serial of the rejected command, 0 = empty slot */
    int32_t command;            /* its code */
    int32_t result;             /* emcmot_command_result_t */
    int32_t reported;           /* 1: the reason was also queued as an operator message */
    char reason[EMCMOT_REASON_LEN];
} emcmot_reject_t;

#define EMCMOT_REJECT_HISTORY 8

/* The command echo: which serial motion handled last and how. */
typedef struct emcmot_echo {
    uint32_t serial;            /* last serial handled (accepted or not) */
    int32_t command;            /* its code */
    int32_t result;             /* its emcmot_command_result_t */
    uint32_t handled;           /* commands handled since load (wraps) */
    uint32_t rejected;          /* commands rejected since load (wraps) */
    uint32_t reject_next;       /* index in reject[] the next rejection goes to */
    emcmot_reject_t reject[EMCMOT_REJECT_HISTORY];
} emcmot_echo_t;

/* One joint (joint[0..joints-1] are valid). */
typedef struct emcmot_joint_status {
    double pos_cmd;             /* commanded joint position (EMC_JOINT_STAT output) */
    double pos_fb;              /* feedback (input) */
    double vel_cmd;             /* commanded velocity */
    double acc_cmd;
    double ferror;              /* current following error */
    double ferror_high_mark;    /* largest |ferror| since ENABLE */
    double ferror_limit;        /* limit in force this cycle */
    double min_ferror, max_ferror;
    double min_pos_limit, max_pos_limit;
    double vel_limit, acc_limit, jerk_limit;
    double backlash;
    double backlash_filt;       /* applied backlash/screw correction */
    double motor_offset;
    double home_offset, home;
    int32_t home_sequence;
    int32_t home_state;         /* joint.N.home-state */
    int32_t active;             /* JOINT_ACTIVATE'd and < num_joints */
    int32_t enabled;            /* amplifier enabled */
    int32_t inpos;
    int32_t homing;
    int32_t homed;
    int32_t error;              /* joint.N.error: faulted or limit tripped */
    int32_t fault;              /* amplifier fault input */
    int32_t ferror_tripped;     /* joint.N.f-errored */
    int32_t min_soft_limit, max_soft_limit;     /* commanded position at/over a soft limit */
    int32_t min_hard_limit, max_hard_limit;     /* switch inputs */
    int32_t override_limits;    /* the switches are masked (OVERRIDE_LIMITS) */
    int32_t jogging;            /* keyboard or wheel jog active */
    int32_t locking_indexer;    /* is a locking indexer (UNLOCK_FIRST) */
    int32_t unlocked;           /* joint.N.is-unlocked */
} emcmot_joint_status_t;

/* One axis X..W (valid when its bit is in the kinematics' axis mask, or always readable). */
typedef struct emcmot_axis_status {
    double min_pos_limit, max_pos_limit;
    double vel_limit, acc_limit, jerk_limit;
    double teleop_pos_cmd;      /* axis.L.teleop-pos-cmd */
    double teleop_vel_cmd;      /* axis.L.teleop-vel-cmd (EMC_AXIS_STAT velocity) */
    double eoffset;             /* applied external offset */
    double eoffset_request;
    int32_t locking_joint;      /* -1 none */
    int32_t teleop_jogging;
} emcmot_axis_status_t;

/* One spindle (spindle[0..spindles-1] valid). */
typedef struct emcmot_spindle_status {
    double speed;               /* commanded rpm, signed (CSS: the css maximum) */
    double speed_out;           /* spindle.N.speed-out: after override and limits */
    double scale;               /* spindle override */
    double css_maximum;
    double css_factor;
    double css_xoffset;
    double speed_fb_rps;        /* spindle.N.speed-in */
    double revs;                /* spindle.N.revs */
    double orient_angle;
    double max_pos_speed, min_pos_speed, max_neg_speed, min_neg_speed, increment;
    int32_t state;              /* 1 on */
    int32_t direction;          /* 1 forward, -1 reverse, 0 off */
    int32_t brake;              /* 1 engaged */
    int32_t increasing;         /* 1 increasing, -1 decreasing, 0 steady */
    int32_t override_enabled;   /* SS_ENABLE */
    int32_t orient_state;       /* 0 idle, 1 orienting, 2 done (spindle.N.is-oriented) */
    int32_t orient_fault;
    int32_t at_speed;
    int32_t inhibit;
    int32_t homed;
    int32_t locked;             /* spindle.N.locked */
} emcmot_spindle_status_t;

/* Everything motion publishes; copied whole by readers (see motion_shm.h). */
typedef struct emcmot_status {
    uint32_t heartbeat;         /* +1 every servo cycle */
    uint32_t config_serial;     /* +1 whenever a configuration command changes limits */
    emcmot_echo_t echo;

    /* configuration in force */
    double cycle_time;          /* servo (trajectory) period, s */
    int32_t joints;             /* SET_NUM_JOINTS (num_joints module parameter until then) */
    int32_t num_extra_joints;
    int32_t spindles;
    int32_t num_dio, num_aio, num_misc_error;
    int32_t kinematics_type;    /* 1 IDENTITY 2 FORWARD_ONLY 3 INVERSE_ONLY 4 BOTH */
    int32_t kinematics_switchable;
    int32_t kinematics_switch_type;     /* motion.switchkins-type in force */
    int32_t planner_type;       /* in force (a deferred switch shows when applied) */
    int32_t debug;
    double vel;                 /* SET_VEL */
    double ini_maxvel;
    double vel_limit;           /* SET_VEL_LIMIT: maxVelocity */
    double acc;                 /* SET_ACC: maxAcceleration */
    double jerk;                /* SET_JERK */
    double max_feed_override;
    double scurve_peak_scale;
    EmcPose world_home;
    EmcPose tool_offset;        /* SET_OFFSET */

    /* state */
    int32_t motion_state;       /* emcmot_motion_state_t */
    int32_t enabled;            /* motion enabled (machine on) */
    int32_t coord;              /* in coordinated mode (or going there) */
    int32_t teleop;
    int32_t inpos;              /* everything at rest where commanded */
    int32_t fault_code;         /* emcmot_fault_t of the last self-disable */
    int32_t homing_active;      /* a homing sequence runs */
    int32_t all_homed;          /* motion.is-all-homed */
    int32_t on_soft_limit;
    int32_t jogging_active;
    int32_t paused;             /* PAUSE in force */
    int32_t stepping;           /* STEP in force */
    int32_t reverse;            /* running backwards */
    int32_t probe_err_inhibit_jog, probe_err_inhibit_home;

    /* planner */
    int32_t queue_depth;        /* segments queued incl. the executing ones */
    int32_t active_depth;
    int32_t queue_full;
    int32_t queue_capacity;     /* planner queue size */
    int32_t exec_id;            /* id of the executing segment (EMC_TRAJ_STAT id, motionLine) */
    state_tag_t exec_tag;       /* its interpreter state */
    int32_t motion_type;        /* of the executing segment, 0 idle */
    int32_t term_cond;
    double tolerance;
    double current_vel;         /* motion.current-vel */
    double requested_vel;       /* motion.requested-vel */
    double distance_to_go;
    EmcPose dtg;
    double feed_scale;          /* FEED_SCALE */
    double rapid_scale;         /* RAPID_SCALE */
    double net_feed_scale;      /* what the planner applied this cycle */
    int32_t feed_scale_enabled; /* FS_ENABLE (feed_override_enabled) */
    int32_t feed_hold_enabled;  /* FH_ENABLE */
    int32_t adaptive_feed_enabled;  /* AF_ENABLE */
    int32_t spindle_sync_waiting;
    EmcPose carte_pos_cmd;      /* commanded pose, machine coordinates (EMC_TRAJ_STAT position) */
    EmcPose carte_pos_fb;       /* feedback pose (actualPosition) */
    int32_t carte_pos_fb_ok;    /* forward kinematics gave carte_pos_fb this cycle */

    /* probing */
    EmcPose probed_pos;
    int32_t probing;
    int32_t probe_tripped;
    int32_t probe_val;          /* motion.probe-input as seen this cycle */
    int32_t probe_type;

    /* external offsets */
    int32_t external_offsets_applied;
    int32_t eoffset_limited;
    EmcPose eoffset_pose;

    /* I/O */
    int32_t synch_di[EMCMOT_MAX_DIO];
    int32_t synch_do[EMCMOT_MAX_DIO];
    double analog_input[EMCMOT_MAX_AIO];
    double analog_output[EMCMOT_MAX_AIO];
    int32_t misc_error[EMCMOT_MAX_MISC_ERROR];

    emcmot_joint_status_t joint[EMCMOT_MAX_JOINTS];
    emcmot_axis_status_t axis[EMCMOT_MAX_AXIS];
    emcmot_spindle_status_t spindle[EMCMOT_MAX_SPINDLES];
} emcmot_status_t;

#ifdef __cplusplus
}
#endif

#endif
