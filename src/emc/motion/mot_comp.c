/* mot_comp.c: step 12: backlash and screw compensation through a velocity/acceleration-limited ramp. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"

/* The correction the joint should have now (motion.md sec. 7). */
static double wanted_correction(mot_joint_t *joint)
{
    if (joint->vel_cmd > 0.0)
        joint->comp_dir = 1;
    else if (joint->vel_cmd < 0.0)
        joint->comp_dir = -1;
    if (joint->comp.count > 0) {
        if (joint->comp_dir == 0)
            return joint->backlash_corr;
        return comp_table_lookup(&joint->comp, joint->pos_cmd, joint->comp_dir);
    }
    return 0.5 * joint->backlash * joint->comp_dir;
}

/* Ramp backlash_filt toward the correction: <= 1/2 the joint's velocity (times the
 * net feed scale) and 1/2 its acceleration, so the correction never jerks the axis. */
static void ramp(mot_joint_t *joint)
{
    simple_tp_t *tp = &joint->backlash_tp;

    tp->pos_cmd = joint->backlash_corr;
    tp->max_vel = 0.5 * joint->vel_limit * fabs(mot->net_feed_scale);
    tp->max_acc = 0.5 * joint->acc_limit;
    tp->enable = 1;
    if (tp->max_acc > 0.0 && tp->max_vel > 0.0) {
        simple_tp_update(tp, mot->servo_period);
    } else if (tp->max_acc <= 0.0) {
        tp->curr_pos = tp->pos_cmd;
        tp->curr_vel = 0.0;
    }
    joint->backlash_filt = tp->curr_pos;
    joint->backlash_vel = tp->curr_vel;
}

/* 12. Every joint in use. */
void mot_compensate(void)
{
    for (int j = 0; j < mot->num_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        joint->backlash_corr = wanted_correction(joint);
        ramp(joint);
    }
}
