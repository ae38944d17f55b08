/* mot_jog.c: jog limits and refusals shared by keyboard and wheel jogs; jog wheels; jog-stop inputs. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_cmd.h"
#include "mot_jog.h"

/* Where joint j may jog: its limits once homed, else +-travel around the feedback. */
void mot_joint_jog_limits(int j, double *lo, double *hi)
{
    const mot_joint_t *joint = &mot->joint[j];

    if (mot->home->joint_homed(j)) {
        *lo = joint->min_limit;
        *hi = joint->max_limit;
    } else {
        double travel = joint->max_limit - joint->min_limit;
        *lo = joint->pos_fb - travel;
        *hi = joint->pos_fb + travel;
    }
}

/* Refuse the command being handled with text (reported) when report is set; returns 1. */
static int refused(int report, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int refused(int report, const char *fmt, ...)
{
    char text[EMCMOT_ERROR_LEN];
    va_list ap;

    if (!report)
        return 1;
    va_start(ap, fmt);
    rtapi_vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1, "%s", text);
    return 1;
}

/* Non-zero (after reporting) when joint j must not jog in direction vel. */
int mot_joint_jog_refused(int j, double vel, int report)
{
    const mot_joint_t *joint = &mot->joint[j];
    int seq = mot->home->joint_home_sequence(j);

    if (!mot->enabled)
        return refused(report, "Can't jog joint when not enabled.");
    if (*mot->pins->jog_inhibit)
        return refused(report, "Cannot jog while jog-inhibit is active.");
    if (joint->locking_indexer)
        return refused(report, "Can't jog locking joint_num=%d", j);
    if (seq < 0 && !mot->home->joint_homed(j)) {
        if (mot->kins->type() == KINEMATICS_IDENTITY)
            return refused(report, "Homing is REQUIRED to jog requested coordinate\n"
                           "because joint (%d) home_sequence is synchronized (%d)\n", j, seq);
        return refused(report, "Cannot jog joint %d because home_sequence is synchronized (%d)",
                       j, seq);
    }
    if (vel > 0.0 && joint->pos_hard)
        return refused(report, "Can't jog joint %d further past max hard limit.", j);
    if (vel < 0.0 && joint->neg_hard)
        return refused(report, "Can't jog joint %d further past min hard limit.", j);
    if (mot->home->joint_homed(j) && vel > 0.0 && joint->pos_cmd >= joint->max_limit)
        return refused(report, "Can't jog joint %d further past max soft limit.", j);
    if (mot->home->joint_homed(j) && vel < 0.0 && joint->pos_cmd <= joint->min_limit)
        return refused(report, "Can't jog joint %d further past min soft limit.", j);
    return 0;
}

/* Non-zero (after reporting) when axis a must not jog in teleop. */
int mot_axis_jog_refused(int a, int report)
{
    (void)a;
    if (!mot->enabled)
        return refused(report, "Can't jog axis when not enabled.");
    if (*mot->pins->jog_inhibit)
        return refused(report, "Cannot jog while jog-inhibit is active.");
    return 0;
}

/* Clamp a jog-accel-fraction pin value: outside 0..1 means 1. */
static double accel_fraction(double f)
{
    return (f > 0.0 && f <= 1.0) ? f : 1.0;
}

/* Counts moved since last cycle (0 on the first read). */
static int count_delta(int now, int *old, int *valid)
{
    int delta = *valid ? now - *old : 0;

    *old = now;
    *valid = 1;
    return delta;
}

/* Wheel-jog target of one planner: position mode adds the distance; velocity mode keeps the
 * target within the stopping distance at full speed, so motion ends soon after the wheel stops. */
static double wheel_target(const simple_tp_t *tp, double distance, int vel_mode, double vmax,
                           double amax)
{
    double target = tp->pos_cmd + distance;

    if (vel_mode && amax > 0.0) {
        double reach = vmax * vmax / (2.0 * amax);
        target = fmin(fmax(target, tp->curr_pos - reach), tp->curr_pos + reach);
    }
    return target;
}

/* Joint jog wheels (free mode, unless motion.jog-inhibit). */
void mot_jog_wheels_joints(void)
{
    for (int j = 0; j < mot->num_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        mot_joint_pins_t *p = &mot->pins->joint[j];
        int delta = count_delta(*p->jog_counts, &joint->jog_counts_old, &joint->jog_counts_valid);
        double distance, target, lo, hi;

        if (delta == 0 || !*p->jog_enable || mot->teleop || mot->coord || !joint->active)
            continue;
        distance = delta * *p->jog_scale;
        if (*mot->pins->jog_inhibit || joint->kb_jog_active || mot->home->homing_active() ||
            mot_joint_jog_refused(j, distance, 0) || !isfinite(distance))
            continue;
        mot_joint_jog_limits(j, &lo, &hi);
        joint->wheel_accel_fraction = accel_fraction(*p->jog_accel_fraction);
        target = wheel_target(&joint->free_tp, distance, *p->jog_vel_mode, joint->vel_limit,
                              fmin(joint->acc_limit, mot->acc) * joint->wheel_accel_fraction);
        joint->free_tp.pos_cmd = fmin(fmax(target, lo), hi);
        joint->free_tp.max_vel = joint->vel_limit;
        joint->free_tp.enable = 1;
        joint->wheel_jog_active = 1;
    }
}

/* Axis jog wheels (teleop mode, unless jog-inhibit or on a soft limit). */
void mot_jog_wheels_axes(void)
{
    for (int a = 0; a < MOT_NUM_AXES; a++) {
        mot_axis_t *axis = &mot->axis[a];
        mot_axis_pins_t *p = &mot->pins->axis[a];
        int delta = count_delta(*p->jog_counts, &axis->jog_counts_old, &axis->jog_counts_valid);
        double distance, target;

        if (delta == 0 || !*p->jog_enable || !mot->teleop)
            continue;
        distance = delta * *p->jog_scale;
        if (*mot->pins->jog_inhibit || mot->on_soft_limit || axis->kb_jog_active ||
            !mot->enabled || !isfinite(distance))
            continue;
        axis->teleop_tp.max_acc = axis->acc_limit * accel_fraction(*p->jog_accel_fraction);
        target = wheel_target(&axis->teleop_tp, distance, *p->jog_vel_mode, axis->vel_limit,
                              axis->teleop_tp.max_acc);
        axis->teleop_tp.pos_cmd = fmin(fmax(target, axis->min_limit), axis->max_limit);
        axis->teleop_tp.max_vel = axis->vel_limit;
        axis->teleop_tp.enable = 1;
        axis->wheel_jog_active = 1;
    }
}

/* Stop every keyboard and wheel jog: decelerate, or at once when immediate. */
static void stop_all_jogs(int immediate)
{
    for (int j = 0; j < mot->num_joints; j++) {
        mot_joint_t *joint = &mot->joint[j];
        if (!joint->kb_jog_active && !joint->wheel_jog_active)
            continue;
        joint->free_tp.enable = 0;
        if (immediate)
            simple_tp_reset(&joint->free_tp, joint->free_tp.curr_pos);
        joint->kb_jog_active = joint->wheel_jog_active = 0;
    }
    for (int a = 0; a < MOT_NUM_AXES; a++) {
        mot_axis_t *axis = &mot->axis[a];
        if (!axis->kb_jog_active && !axis->wheel_jog_active)
            continue;
        axis->teleop_tp.enable = 0;
        if (immediate)
            simple_tp_reset(&axis->teleop_tp, axis->teleop_tp.curr_pos);
        axis->kb_jog_active = axis->wheel_jog_active = 0;
    }
}

/* motion.jog-stop / jog-stop-immediate while a jog runs abort every jog. */
void mot_jog_stop_inputs(void)
{
    if (!mot_jog_active())
        return;
    if (*mot->pins->jog_stop_immediate) {
        stop_all_jogs(1);
        mot_report("Jog aborted by jog-stop-immediate");
    } else if (*mot->pins->jog_stop) {
        stop_all_jogs(0);
        mot_report("Jog aborted by jog-stop");
    }
}

/* Non-zero while any keyboard or wheel jog runs. */
int mot_jog_active(void)
{
    for (int j = 0; j < mot->num_joints; j++)
        if (mot->joint[j].kb_jog_active || mot->joint[j].wheel_jog_active)
            return 1;
    for (int a = 0; a < MOT_NUM_AXES; a++)
        if (mot->axis[a].kb_jog_active || mot->axis[a].wheel_jog_active)
            return 1;
    return 0;
}

/* Abort joint jogs (free mode): decelerate. */
void mot_abort_jogs(void)
{
    stop_all_jogs(0);
}
