/* home_ops.h: the versioned table a homing module (homemod, or [EMCMOT]HOMEMOD) exports as `home_ops`. */
#ifndef HOME_OPS_H
#define HOME_OPS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bump when a member of any struct below is added, removed or changes meaning. */
#define HOME_OPS_VERSION 1u

#define HOME_MAX_JOINTS 16

/* joint.N.home-state values (motion.md sec. 8). */
typedef enum home_state {
    HOME_IDLE = 0, HOME_START, HOME_UNLOCK, HOME_UNLOCK_WAIT,
    HOME_INITIAL_BACKOFF_START, HOME_INITIAL_BACKOFF_WAIT,
    HOME_INITIAL_SEARCH_START, HOME_INITIAL_SEARCH_WAIT,
    HOME_SET_COARSE_POSITION,
    HOME_FINAL_BACKOFF_START, HOME_FINAL_BACKOFF_WAIT,
    HOME_RISE_SEARCH_START, HOME_RISE_SEARCH_WAIT,
    HOME_FALL_SEARCH_START, HOME_FALL_SEARCH_WAIT,
    HOME_SET_SWITCH_POSITION,
    HOME_INDEX_ONLY_START,
    HOME_INDEX_SEARCH_START, HOME_INDEX_SEARCH_WAIT,
    HOME_SET_INDEX_POSITION,
    HOME_FINAL_MOVE_START, HOME_FINAL_MOVE_WAIT,
    HOME_LOCK, HOME_LOCK_WAIT,
    HOME_FINISHED,
    HOME_ABORT
} home_state_t;

/* SET_JOINT_HOMING_PARAMS as task sends it. */
typedef struct home_params {
    double home_offset;         /* position assigned at the switch/index */
    double home;                /* position after the final move */
    double home_final_vel;      /* <= 0: joint MAX_VELOCITY */
    double home_search_vel;     /* signed, 0 = no switch */
    double home_latch_vel;      /* signed */
    int home_flags;             /* EMCMOT_HOME_* (motion_cmd.h) */
    int home_sequence;          /* HOME_SEQUENCE, >100 = not in Home-All, negative = synchronised group */
    int volatile_home;
} home_params_t;

/* One joint as motion and homing share it.  Motion fills the inputs before
 * do_homing() each cycle; homing fills the outputs, motion applies them. */
typedef struct home_joint {
    /* motion -> homing */
    double pos_cmd;             /* joint command (joint coordinates) */
    double pos_fb;              /* joint feedback */
    double vel_limit;           /* joint-mode velocity limit */
    double acc_limit;
    double min_limit, max_limit;
    int active;                 /* joint in use */
    int pos_limit_sw, neg_limit_sw;     /* raw limit switch inputs */
    int free_tp_active;         /* the joint's free planner still moves */
    int is_unlocked;            /* joint.N.is-unlocked (locking indexers) */
    /* homing -> motion */
    int free_tp_enable;         /* drive the joint's free planner ... */
    double free_pos_cmd;        /* ... toward this target ... */
    double free_vel_lim;        /* ... at most this fast */
    int unlock;                 /* joint.N.unlock */
} home_joint_t;

/* What motion hands the homing module at start-up. */
typedef struct home_env {
    int comp_id;                /* motmod's HAL component: homing creates joint.N.* pins under it */
    int num_joints;             /* joints with pins */
    int num_extra_joints;
    double servo_period;        /* s */
    home_joint_t *joints;       /* num_joints entries, owned by motion */
    /* Queue an operator message (realtime safe). */
    void (*report)(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
    /* Shift joint's coordinates so its feedback reads pos (command follows). */
    void (*set_position)(int joint, double pos);
    /* Make the motor zero (encoder reset at the index) read as pos. */
    void (*set_motor_zero)(int joint, double pos);
} home_env_t;

/* The table.  Nothing here allocates, locks or blocks except init. */
typedef struct home_ops {
    unsigned int version;       /* HOME_OPS_VERSION the module was built with */
    unsigned int size;          /* sizeof(home_ops_t) */
    const char *name;

    /* Start-up (rtapi_app_main of motmod): pins, state; 0 or a negative errno. */
    int (*init)(const home_env_t *env);
    /* The cycle, in this order: read pins, run the state machines, write pins.
     * do_homing returns 1 in the cycle a homing run completes with every joint homed. */
    void (*read_inputs)(void);
    int (*do_homing)(void);
    void (*write_outputs)(void);

    /* Requests (from motion's command handler). */
    int (*home_joint)(int joint);           /* -1 = Home-All; 0 or -1 refused (reported) */
    void (*cancel)(void);                   /* abort every homing joint at once */
    int (*set_unhomed)(int joint, int motion_enabled);  /* joint, -1 all, -2 volatile */
    int (*set_params)(int joint, const home_params_t *params);
    int (*update_params)(int joint, double home_offset, double home, int home_sequence);
    void (*set_num_joints)(int num_joints);

    /* Queries. */
    int (*homing_active)(void);
    int (*joint_homing)(int joint);
    int (*joint_homed)(int joint);
    int (*joint_at_home)(int joint);
    int (*joint_home_state)(int joint);
    int (*joint_home_sequence)(int joint);
    int (*joint_sync_final_move)(int joint);  /* negative HOME_SEQUENCE: group homing */
    int (*joint_volatile)(int joint);
    int (*joint_absolute_encoder)(int joint);
    double (*joint_home_offset)(int joint);
    double (*joint_home)(int joint);
} home_ops_t;

/* Check a table found in a module; 0, or -EPROTO/-EINVAL with the reason in why. */
int home_ops_check(const home_ops_t *ops, char *why, size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
