/* tp_ops.h: the versioned table a trajectory-planner module (tpmod) exports as `tp_ops` for motmod. */
#ifndef TP_OPS_H
#define TP_OPS_H

#include <stddef.h>
#include <stdint.h>
#include "emcpos.h"
#include "state_tag.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Bump when a member of any struct below is added, removed or changes meaning. */
#define TP_OPS_VERSION 1u

#define TP_MAX_SPINDLES 8
#define TP_MAX_DIO 64
#define TP_MAX_AIO 64
#define TP_NUM_AXES 9           /* X Y Z A B C U V W, in EmcPose order */

/* Result of every planner call at the realtime boundary; never an errno. */
typedef enum tp_result {
    TP_OK = 0,
    TP_QUEUE_FULL = 1,          /* no free segment; nothing was queued, try again next cycle */
    TP_INVALID_PARAMS = 2,      /* NaN/inf or out-of-range argument; nothing changed */
    TP_BAD_STATE = 3,           /* not allowed now (e.g. adding while an abort is running) */
    TP_NO_JERK_LIMIT = 4,       /* S-curve requested without a usable jerk limit */
    TP_DEFERRED = 5,            /* accepted, takes effect when queued motion completes */
    TP_ZERO_LENGTH = 6          /* segment too short to move; nothing queued (not an error) */
} tp_result_t;

/* Segment motion types (EMC_MOTION_TYPE numbering; 0 = idle). */
typedef enum tp_motion_type {
    TP_MOTION_IDLE = 0,
    TP_MOTION_TRAVERSE = 1,
    TP_MOTION_FEED = 2,
    TP_MOTION_ARC = 3,
    TP_MOTION_TOOLCHANGE = 4,
    TP_MOTION_PROBING = 5,
    TP_MOTION_INDEXROTARY = 6
} tp_motion_type_t;

/* Termination condition as task sends it (motion.md sec. 2). */
typedef enum tp_term_cond {
    TP_TERM_COND_STOP = 0,      /* G61.1: stop at every segment end */
    TP_TERM_COND_EXACT = 1,     /* G61: stop at corners, keep speed through tangent joins */
    TP_TERM_COND_BLEND = 2,     /* G64: blend within the tolerance */
    TP_TERM_COND_TANGENT = 3    /* set internally for tangent joins */
} tp_term_cond_t;

/* Planner types ([TRAJ]PLANNER_TYPE, G64 R). */
typedef enum tp_planner_type {
    TP_PLANNER_TRAPEZOID = 0,
    TP_PLANNER_SCURVE = 1
} tp_planner_type_t;

/* Segment kinds. */
typedef enum tp_segment_kind {
    TP_SEG_LINE = 0,
    TP_SEG_CIRCLE = 1,
    TP_SEG_RIGID_TAP = 2
} tp_segment_kind_t;

/* Bits of tp_segment_t.enables (the override enables queued with the move). */
#define TP_ENABLE_FS 0x01u      /* feed scale (feed override) enabled */
#define TP_ENABLE_SS 0x02u      /* spindle scale enabled */
#define TP_ENABLE_FH 0x04u      /* feed hold enabled */
#define TP_ENABLE_AF 0x08u      /* adaptive feed enabled */

/* One queued move, in machine world coordinates and machine units. */
typedef struct tp_segment {
    tp_segment_kind_t kind;
    tp_motion_type_t motion_type;
    EmcPose end;                /* end point (all nine axes) */
    PmCartesian center;         /* circle: centre */
    PmCartesian normal;         /* circle: unit normal of the plane */
    int turn;                   /* circle: extra full turns (sign gives direction, as canon) */
    double vel;                 /* requested velocity (units/s) */
    double ini_maxvel;          /* machine velocity along this move (units/s) */
    double acc;                 /* machine acceleration along this move (units/s^2) */
    double jerk;                /* machine jerk along this move (units/s^3), 0 = none */
    uint32_t enables;           /* TP_ENABLE_* */
    int atspeed;                /* wait for spindle at-speed before starting */
    int indexer_jnum;           /* joint of a locking indexer this move rotates, -1 none */
    double tap_uu_per_rev;      /* rigid tap: pitch (units per spindle revolution) */
    int32_t id;                 /* motion id (task passes the source line) */
    state_tag_t tag;            /* interpreter state reported while the move runs */
} tp_segment_t;

/* Machine-wide limits and settings; motmod sets them from its SET_* commands. */
typedef struct tp_limits {
    double cycle_time;          /* servo period, s */
    double vmax;                /* SET_VEL: default velocity */
    double ini_maxvel;          /* SET_VEL: [TRAJ] default velocity ceiling */
    double vlimit;              /* SET_VEL_LIMIT: [TRAJ]MAX_LINEAR_VELOCITY */
    double amax;                /* SET_ACC */
    double jmax;                /* SET_JERK: [TRAJ]MAX_LINEAR_JERK, 0 = none */
    double axis_vel[TP_NUM_AXES];   /* [AXIS_L]MAX_VELOCITY */
    double axis_acc[TP_NUM_AXES];   /* [AXIS_L]MAX_ACCELERATION */
    double axis_jerk[TP_NUM_AXES];  /* [AXIS_L]MAX_JERK, 0 = none */
    double max_feed_override;   /* SET_MAX_FEED_OVERRIDE */
    double scurve_peak_scale;   /* SET_SCURVE_PEAK_SCALE */
    int arc_blend_enable;       /* SETUP_ARC_BLENDS */
    int arc_blend_fallback_enable;
    int arc_blend_optimization_depth;
    double arc_blend_gap_cycles;
    double arc_blend_ramp_freq;
    double arc_blend_tangent_kink_ratio;
} tp_limits_t;

/* Spindle state the planner reads each cycle (index 0..TP_MAX_SPINDLES-1). */
typedef struct tp_spindle_in {
    double revs;                /* spindle.N.revs */
    double speed_rps;           /* spindle.N.speed-in */
    double speed_cmd_rps;       /* commanded speed (sign = direction) */
    int at_speed;               /* spindle.N.at-speed */
    int index_enable;           /* spindle.N.index-enable as read this cycle */
} tp_spindle_in_t;

/* Everything the planner reads in one servo cycle. */
typedef struct tp_cycle_in {
    double feed_scale;          /* feed override (1.0 = 100 %) */
    double rapid_scale;         /* rapid override */
    double adaptive_feed;       /* motion.adaptive-feed (negative asks for reverse run) */
    int feed_hold;              /* motion.feed-hold */
    int feed_inhibit;           /* motion.feed-inhibit */
    int num_spindles;
    tp_spindle_in_t spindle[TP_MAX_SPINDLES];
    int indexer_unlocked;       /* joint.N.is-unlocked of the active indexer joint */
} tp_cycle_in_t;

/* Everything the planner tells motion after one servo cycle. */
typedef struct tp_cycle_out {
    EmcPose pos;                /* commanded world position */
    double current_vel;         /* path speed incl. overrides (motion.current-vel) */
    double requested_vel;       /* programmed speed capped by machine maxima (motion.requested-vel) */
    double distance_to_go;      /* in the executing segment */
    EmcPose dtg;                /* per-axis distance to go */
    double net_feed_scale;      /* the scale applied this cycle */
    tp_motion_type_t motion_type;   /* of the executing segment, 0 when idle */
    int32_t exec_id;            /* id of the executing segment */
    state_tag_t exec_tag;       /* tag of the executing segment */
    int done;                   /* queue empty and at rest */
    int queue_depth;            /* segments queued, executing ones included */
    int active_depth;           /* segments moving now (blends overlap two) */
    int queue_full;
    int paused;                 /* paused and at rest */
    int reverse;                /* running backwards (motion.tp-reverse) */
    int spindle_sync_waiting;   /* waiting for at-speed or the index */
    int rigid_tap_state;        /* 0 TAPPING .. 4 FINAL_PLACEMENT, -1 not tapping */
    /* Synchronised outputs that take effect this cycle. */
    uint64_t dout_change_mask;  /* bit i: digital-out i changes to bit i of dout_values */
    uint64_t dout_values;
    uint64_t aout_change_mask;  /* bit i: analog-out i changes to aout_values[i] */
    double aout_values[TP_MAX_AIO];
    /* Requests to motion for spindles and indexers. */
    int arm_index[TP_MAX_SPINDLES];         /* set spindle.N.index-enable this cycle */
    int spindle_reverse[TP_MAX_SPINDLES];   /* rigid tap: 1 run reversed, 0 as commanded */
    int unlock_joint;           /* joint to unlock (locking indexer), -1 none */
} tp_cycle_out_t;

typedef struct tp_planner tp_planner_t;     /* one planner; opaque to motion */

/* The table.  Every function returns at once: no allocation, no locks, no
 * unbounded loops (the planner does its work in bounded slices per cycle). */
typedef struct tp_ops {
    unsigned int version;       /* TP_OPS_VERSION the module was built with */
    unsigned int size;          /* sizeof(tp_ops_t) the module was built with */
    const char *name;           /* module name, for messages */

    /* Life cycle (called from rtapi_app_main/exit of motmod, never in the cycle). */
    tp_planner_t *(*create)(int queue_size);
    void (*destroy)(tp_planner_t *tp);

    /* Configuration. */
    tp_result_t (*set_limits)(tp_planner_t *tp, const tp_limits_t *limits);
    tp_result_t (*set_term_cond)(tp_planner_t *tp, tp_term_cond_t cond, double tolerance);
    tp_result_t (*set_planner_type)(tp_planner_t *tp, tp_planner_type_t type);
    tp_result_t (*set_pos)(tp_planner_t *tp, const EmcPose *pos);
    tp_result_t (*set_spindle_sync)(tp_planner_t *tp, int spindle, double uu_per_rev,
                                    int velocity_mode);
    tp_result_t (*set_dout)(tp_planner_t *tp, int index, int start_value, int end_value);
    tp_result_t (*set_aout)(tp_planner_t *tp, int index, double start_value, double end_value);
    tp_result_t (*set_run_dir)(tp_planner_t *tp, int reverse);

    /* Queue. */
    tp_result_t (*add)(tp_planner_t *tp, const tp_segment_t *seg);
    tp_result_t (*clear)(tp_planner_t *tp);
    tp_result_t (*pause)(tp_planner_t *tp);
    tp_result_t (*resume)(tp_planner_t *tp);
    tp_result_t (*abort)(tp_planner_t *tp);

    /* The servo cycle. */
    tp_result_t (*run_cycle)(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out);

    /* Queries (cheap; usable between cycles). */
    int (*is_done)(const tp_planner_t *tp);
    int (*queue_depth)(const tp_planner_t *tp);
    int (*queue_full)(const tp_planner_t *tp);
    int (*get_pos)(const tp_planner_t *tp, EmcPose *pos);
    int (*planner_type)(const tp_planner_t *tp);
} tp_ops_t;

/* Check a table found in a module; 0, or -EPROTO/-EINVAL with the reason in why. */
int tp_ops_check(const tp_ops_t *ops, char *why, size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
