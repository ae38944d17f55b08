/* motion_cmd.h: the commands task (or a test) queues to motion, with LinuxCNC's EMCMOT numbering. */
#ifndef MOTION_CMD_H
#define MOTION_CMD_H

#include <stddef.h>
#include <stdint.h>
#include "emcpos.h"
#include "state_tag.h"

#ifdef __cplusplus
extern "C" {
#endif

#define EMCMOT_MAX_JOINTS 16
#define EMCMOT_MAX_AXIS 9           /* X Y Z A B C U V W, EmcPose order */
#define EMCMOT_MAX_SPINDLES 8
#define EMCMOT_MAX_DIO 64
#define EMCMOT_MAX_AIO 64
#define EMCMOT_MAX_MISC_ERROR 64

/* Command codes in LinuxCNC's enum order (motion.md sec. 2); ABORT is 1. */
typedef enum emcmot_command_code {
    EMCMOT_ABORT = 1,               /* stop jogs/homing (free) or abort the planner (coord) */
    EMCMOT_ENABLE,                  /* machine on: enable motion and the amplifiers */
    EMCMOT_DISABLE,                 /* machine off */
    EMCMOT_PAUSE,                   /* hold the coordinated queue (feed scale 0) */
    EMCMOT_REVERSE,                 /* run the queue backwards */
    EMCMOT_FORWARD,                 /* run the queue forwards again */
    EMCMOT_RESUME,                  /* release a pause */
    EMCMOT_STEP,                    /* run one segment, then pause */
    EMCMOT_FREE,                    /* joint mode */
    EMCMOT_COORD,                   /* coordinated mode (planner queue) */
    EMCMOT_TELEOP,                  /* world jog mode */
    EMCMOT_SPINDLE_SCALE,           /* spindle override: spindle, scale */
    EMCMOT_SS_ENABLE,               /* spindle override enable: spindle, enable */
    EMCMOT_FEED_SCALE,              /* feed override: scale */
    EMCMOT_RAPID_SCALE,             /* rapid override: scale */
    EMCMOT_FS_ENABLE,               /* feed override enable: enable */
    EMCMOT_FH_ENABLE,               /* feed hold enable: enable */
    EMCMOT_AF_ENABLE,               /* adaptive feed enable: enable */
    EMCMOT_OVERRIDE_LIMITS,         /* mask tripped limit switches: joint (-1 all), enable */
    EMCMOT_SET_LINE,                /* queue a line: pos, id, motion_type, vel, ini_maxvel, acc, jerk, tag */
    EMCMOT_SET_CIRCLE,              /* queue an arc: pos, center, normal, turn + line fields */
    EMCMOT_CLEAR_PROBE_FLAGS,
    EMCMOT_PROBE,                   /* queue a probe move: line fields + probe_type */
    EMCMOT_RIGID_TAP,               /* queue a rigid tap: pos, vel, ini_maxvel, acc, tap_pitch, spindle */
    EMCMOT_SET_VEL,                 /* vel, ini_maxvel */
    EMCMOT_SET_VEL_LIMIT,           /* vel */
    EMCMOT_SET_ACC,                 /* acc */
    EMCMOT_SET_JERK,                /* jerk */
    EMCMOT_SET_PLANNER_TYPE,        /* planner_type */
    EMCMOT_SET_SCURVE_PEAK_SCALE,   /* scale */
    EMCMOT_SET_TERM_COND,           /* term_cond, tolerance */
    EMCMOT_SET_NUM_JOINTS,          /* count */
    EMCMOT_SET_NUM_SPINDLES,        /* count */
    EMCMOT_SET_WORLD_HOME,          /* pos */
    EMCMOT_SET_DEBUG,               /* debug */
    EMCMOT_SET_DOUT,                /* io_index, now, dout_start, dout_end */
    EMCMOT_SET_AOUT,                /* io_index, now, aout_start, aout_end */
    EMCMOT_SET_SPINDLESYNC,         /* spindle, spindle_sync (units/rev), sync_velocity_mode */
    EMCMOT_SPINDLE_ON,              /* spindle, speed, css_factor, css_xoffset, wait_for_at_speed */
    EMCMOT_SPINDLE_OFF,             /* spindle (-1 all), wait_for_at_speed */
    EMCMOT_SPINDLE_INCREASE,        /* spindle */
    EMCMOT_SPINDLE_DECREASE,        /* spindle */
    EMCMOT_SPINDLE_BRAKE_ENGAGE,    /* spindle */
    EMCMOT_SPINDLE_BRAKE_RELEASE,   /* spindle */
    EMCMOT_SPINDLE_ORIENT,          /* spindle, orientation, orient_mode */
    EMCMOT_SET_OFFSET,              /* pos: tool offset (motion.tooloffset.*) */
    EMCMOT_SET_MAX_FEED_OVERRIDE,   /* scale */
    EMCMOT_SETUP_ARC_BLENDS,        /* arc_blend_* */
    EMCMOT_SET_PROBE_ERR_INHIBIT,   /* probe_jog_err_inhibit, probe_home_err_inhibit */
    EMCMOT_JOG_CONT,                /* joint (free) or axis (teleop, joint -1), vel (signed) */
    EMCMOT_JOG_INCR,                /* joint or axis, vel, offset (distance, signed) */
    EMCMOT_JOG_ABS,                 /* joint or axis, vel, offset (target position) */
    EMCMOT_JOG_ABORT,               /* joint or axis */
    EMCMOT_JOINT_ACTIVATE,          /* joint */
    EMCMOT_JOINT_DEACTIVATE,        /* joint */
    EMCMOT_JOINT_HOME,              /* joint, -1 = home all */
    EMCMOT_JOINT_UNHOME,            /* joint, -1 = all, -2 = VOLATILE_HOME joints */
    EMCMOT_SET_JOINT_POSITION_LIMITS,   /* joint, min_limit, max_limit */
    EMCMOT_SET_JOINT_BACKLASH,      /* joint, backlash */
    EMCMOT_SET_JOINT_MIN_FERROR,    /* joint, min_ferror */
    EMCMOT_SET_JOINT_MAX_FERROR,    /* joint, max_ferror */
    EMCMOT_SET_JOINT_VEL_LIMIT,     /* joint, vel */
    EMCMOT_SET_JOINT_ACC_LIMIT,     /* joint, acc */
    EMCMOT_SET_JOINT_HOMING_PARAMS, /* joint, home_*, home_flags, home_sequence, volatile_home */
    EMCMOT_SET_JOINT_JERK_LIMIT,    /* joint, jerk */
    EMCMOT_UPDATE_JOINT_HOMING_PARAMS,  /* joint, home_offset, home, home_sequence */
    EMCMOT_SET_JOINT_MOTOR_OFFSET,  /* joint, offset */
    EMCMOT_SET_JOINT_COMP,          /* joint, comp_nominal, comp_forward, comp_reverse (one table row) */
    EMCMOT_SET_AXIS_POSITION_LIMITS,    /* axis, min_limit, max_limit */
    EMCMOT_SET_AXIS_VEL_LIMIT,      /* axis, vel, ext_offset_vel (the eoffset share) */
    EMCMOT_SET_AXIS_ACC_LIMIT,      /* axis, acc, ext_offset_acc (the eoffset share) */
    EMCMOT_SET_AXIS_LOCKING_JOINT,  /* axis, locking_joint */
    EMCMOT_SET_AXIS_JERK_LIMIT,     /* axis, jerk */
    EMCMOT_SET_SPINDLE_PARAMS       /* spindle, max/min_pos_speed, max/min_neg_speed, spindle_increment, home_* */
} emcmot_command_code_t;

#define EMCMOT_FIRST_COMMAND EMCMOT_ABORT
#define EMCMOT_LAST_COMMAND EMCMOT_SET_SPINDLE_PARAMS

/* Result of one command, echoed with its serial (LinuxCNC numbering). */
typedef enum emcmot_command_result {
    EMCMOT_COMMAND_OK = 0,
    EMCMOT_COMMAND_UNKNOWN_COMMAND = 1,     /* code outside the enum */
    EMCMOT_COMMAND_INVALID_COMMAND = 2,     /* not allowed in this state (mode, enable, homing) */
    EMCMOT_COMMAND_INVALID_PARAMS = 3,      /* out of range, NaN/inf, limits exceeded */
    EMCMOT_COMMAND_BAD_EXEC = 4             /* accepted but failed (e.g. planner queue refused it) */
} emcmot_command_result_t;

/* JOINT_HOME / JOINT_UNHOME joint numbers with a special meaning. */
#define EMCMOT_JOINT_ALL (-1)
#define EMCMOT_JOINT_VOLATILE (-2)

/* SET_JOINT_HOMING_PARAMS home_flags (motion.md sec. 8). */
#define EMCMOT_HOME_IGNORE_LIMITS 0x01
#define EMCMOT_HOME_USE_INDEX 0x02
#define EMCMOT_HOME_IS_SHARED 0x04
#define EMCMOT_HOME_UNLOCK_FIRST 0x08
#define EMCMOT_HOME_ABSOLUTE_ENCODER 0x10
#define EMCMOT_HOME_NO_REHOME 0x20
#define EMCMOT_HOME_NO_FINAL_MOVE 0x40
#define EMCMOT_HOME_INDEX_NO_ENCODER_RESET 0x80

/* PROBE probe_type bits: G38.2 = 0, G38.3 = NO_ERROR, G38.4 = AWAY, G38.5 = AWAY|NO_ERROR. */
#define EMCMOT_PROBE_NO_ERROR 0x01
#define EMCMOT_PROBE_AWAY 0x02

/* One command.  Fixed size; every field is named.  All floating-point fields
 * come first (from `pos` up to `int_fields_begin`) so one loop can refuse a
 * NaN/inf anywhere; motion refuses such a command and never stores it. */
typedef struct emcmot_command {
    uint32_t serial;            /* set by emcmot_push(); echoed in the status */
    int32_t command;            /* emcmot_command_code_t */

    /* ---- floating point (all must be finite) ---- */
    EmcPose pos;                /* move end point; SET_WORLD_HOME pose; SET_OFFSET tool offset */
    PmCartesian center;         /* SET_CIRCLE centre */
    PmCartesian normal;         /* SET_CIRCLE plane normal */
    double vel;                 /* requested velocity (moves, SET_VEL, limits, jogs) */
    double ini_maxvel;          /* machine velocity along a move; SET_VEL ceiling */
    double acc;                 /* move, SET_ACC, joint/axis acceleration limit */
    double jerk;                /* move, SET_JERK, joint/axis jerk limit (0 = none) */
    double tolerance;           /* SET_TERM_COND blend tolerance */
    double scale;               /* FEED/RAPID/SPINDLE_SCALE, SET_MAX_FEED_OVERRIDE, SET_SCURVE_PEAK_SCALE */
    double offset;              /* JOG_INCR distance, JOG_ABS target, SET_JOINT_MOTOR_OFFSET */
    double min_limit;           /* SET_JOINT/AXIS_POSITION_LIMITS */
    double max_limit;
    double backlash;            /* SET_JOINT_BACKLASH */
    double min_ferror;          /* SET_JOINT_MIN_FERROR */
    double max_ferror;          /* SET_JOINT_MAX_FERROR */
    double home;                /* HOMING_PARAMS: position after the final move ([JOINT_n]HOME) */
    double home_offset;         /* HOMING_PARAMS: position assigned at the switch/index */
    double home_final_vel;      /* HOMING_PARAMS: -1 = MAX_VELOCITY */
    double home_search_vel;
    double home_latch_vel;
    double comp_nominal;        /* SET_JOINT_COMP: nominal position */
    double comp_forward;        /* correction moving + (nominal - actual) */
    double comp_reverse;        /* correction moving - */
    double spindle_sync;        /* SET_SPINDLESYNC: units per revolution, 0 = off */
    double tap_pitch;           /* RIGID_TAP: units per revolution (0 = last SET_SPINDLESYNC) */
    double speed;               /* SPINDLE_ON: rpm, sign = direction; CSS: surface speed */
    double css_factor;          /* SPINDLE_ON: constant surface speed factor, 0 = off */
    double css_xoffset;         /* SPINDLE_ON: X of the spindle centre for CSS */
    double orientation;         /* SPINDLE_ORIENT: angle in degrees */
    double aout_start;          /* SET_AOUT: value at the start of the next move (or now) */
    double aout_end;            /* SET_AOUT: value at its end */
    double max_pos_speed;       /* SET_SPINDLE_PARAMS: rpm limits, forward */
    double min_pos_speed;
    double max_neg_speed;       /* reverse limits (negative numbers) */
    double min_neg_speed;
    double spindle_increment;   /* SET_SPINDLE_PARAMS: rpm per INCREASE/DECREASE */
    double ext_offset_vel;      /* SET_AXIS_VEL_LIMIT: velocity reserved for external offsets */
    double ext_offset_acc;      /* SET_AXIS_ACC_LIMIT: acceleration reserved for external offsets */
    double arc_blend_gap_cycles;        /* SETUP_ARC_BLENDS */
    double arc_blend_ramp_freq;
    double arc_blend_tangent_kink_ratio;

    /* ---- integers ---- */
    int32_t int_fields_begin;   /* marker, always 0: the floating-point block ends here */
    int32_t joint;              /* joint number (or EMCMOT_JOINT_*); -1 for axis jogs */
    int32_t axis;               /* axis 0..8 (X..W) for axis commands and teleop jogs, else -1 */
    int32_t spindle;            /* spindle 0..7; -1 = all (SPINDLE_OFF) */
    int32_t count;              /* SET_NUM_JOINTS / SET_NUM_SPINDLES */
    int32_t id;                 /* move id (task passes the source line) */
    int32_t motion_type;        /* EMC_MOTION_TYPE: 1 traverse, 2 feed, 3 arc, 4 toolchange, 5 probing, 6 indexrotary */
    int32_t turn;               /* SET_CIRCLE extra turns */
    int32_t term_cond;          /* SET_TERM_COND: 0 STOP (G61.1), 1 EXACT (G61), 2 BLEND (G64) */
    int32_t probe_type;         /* PROBE: EMCMOT_PROBE_* bits */
    int32_t enable;             /* *_ENABLE, OVERRIDE_LIMITS: 0/1 */
    int32_t planner_type;       /* SET_PLANNER_TYPE: 0 trapezoid, 1 S-curve */
    int32_t debug;              /* SET_DEBUG */
    int32_t io_index;           /* SET_DOUT / SET_AOUT: output number */
    int32_t now;                /* SET_DOUT / SET_AOUT: 1 immediate (M64/M65/M68), 0 synced (M62/M63/M67) */
    int32_t dout_start;         /* SET_DOUT: value at the start of the next move (or now) */
    int32_t dout_end;           /* SET_DOUT: value at its end */
    int32_t sync_velocity_mode; /* SET_SPINDLESYNC: 1 velocity mode (G95-like), 0 position (G33) */
    int32_t wait_for_at_speed;  /* SPINDLE_ON/OFF: the next feed move waits for at-speed */
    int32_t orient_mode;        /* SPINDLE_ORIENT: 0 either way, 1 clockwise, 2 counter-clockwise */
    int32_t home_flags;         /* HOMING_PARAMS: EMCMOT_HOME_* */
    int32_t home_sequence;      /* HOMING_PARAMS: HOME_SEQUENCE (999 = none) */
    int32_t volatile_home;      /* HOMING_PARAMS: VOLATILE_HOME */
    int32_t locking_joint;      /* SET_AXIS_LOCKING_JOINT: joint, -1 none */
    int32_t arc_blend_enable;   /* SETUP_ARC_BLENDS */
    int32_t arc_blend_fallback_enable;
    int32_t arc_blend_optimization_depth;
    int32_t probe_jog_err_inhibit;      /* SET_PROBE_ERR_INHIBIT */
    int32_t probe_home_err_inhibit;
    state_tag_t tag;            /* moves: interpreter state shown while the move runs */
} emcmot_command_t;

/* Number of doubles in the floating-point block of emcmot_command_t. */
#define EMCMOT_COMMAND_DOUBLES \
    ((offsetof(emcmot_command_t, int_fields_begin) - offsetof(emcmot_command_t, pos)) / sizeof(double))

/* Name of a command code ("SET_LINE"), or NULL for an unknown code. */
const char *emcmot_command_name(int code);
/* Name of a result code ("INVALID_PARAMS"). */
const char *emcmot_result_name(int result);
/* Clear *cmd and set its code: ints that mean "none" are -1, everything else 0. */
void emcmot_command_init(emcmot_command_t *cmd, emcmot_command_code_t code);
/* 0 when every floating-point field is finite; else -EINVAL and the field's name in *field. */
int emcmot_command_check_finite(const emcmot_command_t *cmd, const char **field);

#ifdef __cplusplus
}
#endif

#endif
