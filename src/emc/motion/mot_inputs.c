/* mot_inputs.c: step 3 of the servo loop (feedback, following error, switches, feed scale) and the homing I/O. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"

/* Net feed scale outside coordinated mode (coord takes the planner's). */
static void free_feed_scale(void)
{
    double scale = 1.0;

    if (mot->coord)
        return;
    if (mot->teleop && mot->fs_enabled)
        scale *= mot->feed_scale;
    if (mot->af_enabled) {
        double af = fabs(*mot->pins->adaptive_feed);
        scale *= isfinite(af) ? fmin(af, mot->max_feed_override) : 0.0;
    }
    if (mot->fh_enabled && *mot->pins->feed_hold)
        scale = 0.0;
    if (*mot->pins->feed_inhibit)
        scale = 0.0;
    mot->net_feed_scale = scale;
}

/* Following-error limit: FERROR scaled by speed, floored at MIN_FERROR. */
static double ferror_limit(const mot_joint_t *joint)
{
    double lim = joint->max_ferror;

    if (joint->vel_limit > 0.0)
        lim = joint->max_ferror * fabs(joint->vel_cmd) / joint->vel_limit;
    return lim < joint->min_ferror ? joint->min_ferror : lim;
}

/* One joint: feedback, following error, limit switches, amplifier fault. */
static void joint_inputs(int j)
{
    mot_joint_t *joint = &mot->joint[j];
    mot_joint_pins_t *p = &mot->pins->joint[j];
    double fb = *p->motor_pos_fb;
    int extra = j >= mot->num_kins_joints;

    joint->motor_pos_fb = isfinite(fb) ? fb : joint->motor_pos_fb;
    joint->pos_fb = joint->motor_pos_fb - joint->backlash_filt - joint->motor_offset;
    joint->ferror = joint->pos_cmd - joint->pos_fb;
    if (extra && mot->home->joint_homed(j))
        joint->ferror = 0.0;
    joint->ferror_limit = ferror_limit(joint);
    if (fabs(joint->ferror) > joint->ferror_high_mark)
        joint->ferror_high_mark = fabs(joint->ferror);
    joint->pos_hard = *p->pos_lim_sw_in != 0;
    joint->neg_hard = *p->neg_lim_sw_in != 0;
    joint->amp_fault = *p->amp_fault_in != 0;
}

/* Digital and analog inputs into the status arrays. */
static void io_inputs(void)
{
    for (int i = 0; i < mot->num_dio; i++)
        mot->status.synch_di[i] = *mot->pins->digital_in[i] != 0;
    for (int i = 0; i < mot->num_aio; i++)
        mot->status.analog_input[i] = *mot->pins->analog_in[i];
    for (int i = 0; i < mot->num_misc_error; i++)
        mot->status.misc_error[i] = *mot->pins->misc_error[i] != 0;
}

/* 3. Process inputs. */
void mot_process_inputs(void)
{
    mot_spindle_inputs();
    free_feed_scale();
    for (int j = 0; j < mot->max_joints; j++)
        joint_inputs(j);
    io_inputs();
}

/* What the homing module sees of each joint this cycle. */
void mot_homing_inputs_update(void)
{
    for (int j = 0; j < mot->max_joints; j++) {
        const mot_joint_t *joint = &mot->joint[j];
        home_joint_t *h = &mot->home_joints[j];
        h->pos_cmd = joint->pos_cmd;
        h->pos_fb = joint->pos_fb;
        h->vel_limit = joint->vel_limit;
        h->acc_limit = fmin(joint->acc_limit, mot->acc);
        h->min_limit = joint->min_limit;
        h->max_limit = joint->max_limit;
        h->active = joint->active && j < mot->num_joints;
        h->pos_limit_sw = joint->pos_hard;
        h->neg_limit_sw = joint->neg_hard;
        h->free_tp_active = joint->free_tp.active;
        h->is_unlocked = mot->pins->joint[j].is_unlocked ? *mot->pins->joint[j].is_unlocked : 1;
    }
}

/* Homing drives the free planners of the joints it homes. */
void mot_homing_outputs_apply(void)
{
    for (int j = 0; j < mot->num_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        const home_joint_t *h = &mot->home_joints[j];
        if (mot->pins->joint[j].unlock)
            *mot->pins->joint[j].unlock = h->unlock;
        if (!mot->home->joint_homing(j))
            continue;
        joint->free_tp.enable = h->free_tp_enable;
        joint->free_tp.pos_cmd = h->free_pos_cmd;
        joint->free_tp.max_vel = fmin(h->free_vel_lim, joint->vel_limit);
        joint->kb_jog_active = joint->wheel_jog_active = 0;
    }
}
