/* home_priv.h: homemod's state: per-joint homing state machines and the sequence that runs them. */
#ifndef HOME_PRIV_H
#define HOME_PRIV_H

#include "hal.h"
#include "home_ops.h"
#include "motion_cmd.h"

#define HOME_PAUSE_S 0.1            /* pause before each homing move */
#define HOME_TRAVEL_MARGIN 1.1      /* search/latch moves go at most 1.1 x (MAX_LIMIT - MIN_LIMIT) */
#define HOME_TRAVEL_MAX 1e9         /* larger travel means "no limits configured" */
#define HOME_SEQUENCE_NONE 100      /* |HOME_SEQUENCE| above this: not in Home-All */

/* Pins of one joint the homing module owns. */
typedef struct home_pins {
    hal_bit_t *home_sw_in;
    hal_bit_t *homing;
    hal_bit_t *homed;
    hal_s32_t *home_state;
    hal_bit_t *index_enable;
} home_pins_t;

/* One joint's homing state. */
typedef struct home_jstate {
    home_params_t params;
    int state;                  /* home_state_t */
    int homing;                 /* in the current run */
    int homed;
    int home_sw;                /* home-sw-in this cycle */
    int index_enable;           /* index-enable as read this cycle */
    int pause_cycles;           /* cycles left of the pause before a move */
    int pause_started;
    int chain;                  /* the handler moved on to a state that runs this cycle */
    double latch_fb;            /* feedback where the switch or index latched */
    int sync_group;             /* |sequence| of a negative sequence, 0 = none */
} home_jstate_t;

/* The whole module. */
typedef struct home {
    home_env_t env;
    int num_joints;             /* joints in use (SET_NUM_JOINTS) */
    home_jstate_t joint[HOME_MAX_JOINTS];
    home_pins_t *pins;          /* hal_malloc'ed, env.num_joints entries */
    int run_active;             /* a homing run (Home-All or one joint/group) is going */
    int run_all;                /* the run is Home-All: it steps through sequence numbers */
    int run_sequence;           /* sequence number running now */
    int run_completed;          /* set in the cycle a run ends normally */
} home_t;

extern home_t home;

/* home_joint.c: one cycle of one joint's state machine. */
void home_joint_cycle(int j);
/* Begin homing joint j (state START). */
void home_joint_begin(int j);
/* Stop joint j's homing motion at once and mark it idle (not homed). */
void home_joint_stop(int j);

/* home_seq.c */
int home_seq_start_all(void);
int home_seq_start_joint(int j);
void home_seq_cycle(void);
void home_seq_abort(void);
int home_seq_group_ready(int j, int state);
int home_joint_in_use(int j);

#endif
