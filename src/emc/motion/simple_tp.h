/* simple_tp.h: one-dimensional trapezoid planner for free-mode joints, teleop axes and external offsets. */
#ifndef SIMPLE_TP_H
#define SIMPLE_TP_H

/* Moves curr_pos toward pos_cmd within max_vel and max_acc; pure, no HAL. */
typedef struct simple_tp {
    double pos_cmd;     /* target */
    double max_vel;     /* > 0 */
    double max_acc;     /* > 0 */
    int enable;         /* 0: decelerate to a stop where it is */
    double curr_pos;
    double curr_vel;
    double curr_acc;    /* acceleration applied in the last update */
    int active;         /* moving or not yet at the target */
} simple_tp_t;

/* One period: accelerate, cruise or brake so the move ends at pos_cmd without overshoot. */
void simple_tp_update(simple_tp_t *tp, double period);
/* Place the planner at rest at pos. */
void simple_tp_reset(simple_tp_t *tp, double pos);
/* Distance needed to stop from the current velocity. */
double simple_tp_stop_distance(const simple_tp_t *tp);

#endif
