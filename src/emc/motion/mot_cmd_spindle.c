/* mot_cmd_spindle.c: spindle commands: on/off/speed steps, brake, orient, override, limits. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_cmd.h"

#define ORIENT_NONE 0
#define ORIENT_IN_PROGRESS 1

/* Stop the orient cycle of s (M3/M4/M5 end it). */
static void end_orient(mot_spindle_t *s)
{
    s->orient_state = ORIENT_NONE;
    s->locked = 0;
}

/* A commanded speed within the [SPINDLE_n] forward/reverse limits (status shows this speed). */
static double limited_speed(const mot_spindle_t *s, double rpm)
{
    if (rpm > 0.0)
        return fmax(fmin(rpm, s->max_pos_speed), s->min_pos_speed);
    if (rpm < 0.0)
        return fmin(fmax(rpm, s->max_neg_speed), s->min_neg_speed);
    return rpm;
}

/* SPINDLE_SCALE: spindle override. */
int mot_cmd_spindle_scale(const emcmot_command_t *c)
{
    int n = mot_cmd_spindle(c, "Attempt to set override of non-existent spindle");

    if (n < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (c->scale < 0.0)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "SPINDLE_SCALE: %g is negative",
                          c->scale);
    mot->spindle[n].scale = c->scale;
    return EMCMOT_COMMAND_OK;
}

/* SS_ENABLE: spindle override enable (M51). */
int mot_cmd_ss_enable(const emcmot_command_t *c)
{
    int n = mot_cmd_spindle(c, "Attempt to enable override of non-existent spindle");

    if (n < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->spindle[n].override_enabled = c->enable != 0;
    return EMCMOT_COMMAND_OK;
}

/* SPINDLE_ON: speed (sign = direction), constant surface speed, wait for at-speed. */
int mot_cmd_spindle_on(const emcmot_command_t *c)
{
    int n = mot_cmd_spindle(c, "Attempt to start non-existent spindle");
    mot_spindle_t *s;

    if (n < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    s = &mot->spindle[n];
    end_orient(s);
    s->css_factor = c->css_factor;
    /* a constant surface speed's rpm cap is its own limit: the output clamps the result */
    s->speed = c->css_factor != 0.0 ? c->speed : limited_speed(s, c->speed);
    s->css_xoffset = c->css_xoffset;
    s->on = 1;
    s->direction = c->speed < 0.0 ? -1 : 1;
    s->brake = 0;
    s->increasing = 0;
    if (c->wait_for_at_speed)
        mot->atspeed_next_feed = 1;
    return EMCMOT_COMMAND_OK;
}

/* Turn spindle n off. */
static void spindle_off(int n)
{
    mot_spindle_t *s = &mot->spindle[n];

    end_orient(s);
    s->on = 0;
    s->speed = 0.0;
    s->css_factor = 0.0;
    s->direction = 0;
    s->brake = 1;
    s->increasing = 0;
}

/* SPINDLE_OFF: one spindle, or all with -1. */
int mot_cmd_spindle_off(const emcmot_command_t *c)
{
    if (c->spindle == -1) {
        for (int n = 0; n < mot->num_spindles; n++)
            spindle_off(n);
    } else {
        int n = mot_cmd_spindle(c, "Attempt to stop non-existent spindle");
        if (n < 0)
            return EMCMOT_COMMAND_INVALID_PARAMS;
        spindle_off(n);
    }
    if (c->wait_for_at_speed)
        mot->atspeed_next_feed = 1;
    return EMCMOT_COMMAND_OK;
}

/* Change a running spindle's speed by one increment in its direction. */
static int speed_step(const emcmot_command_t *c, int sign)
{
    int n = mot_cmd_spindle(c, "Attempt to change speed of non-existent spindle");
    mot_spindle_t *s;

    if (n < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    s = &mot->spindle[n];
    if (!s->on || s->direction == 0)
        return EMCMOT_COMMAND_OK;
    s->speed += sign * s->direction * s->increment;
    if (s->speed * s->direction < 0.0)
        s->speed = 0.0;
    else if (s->css_factor == 0.0)
        s->speed = limited_speed(s, s->speed);
    s->increasing = sign;
    return EMCMOT_COMMAND_OK;
}

/* SPINDLE_INCREASE. */
int mot_cmd_spindle_increase(const emcmot_command_t *c)
{
    return speed_step(c, 1);
}

/* SPINDLE_DECREASE. */
int mot_cmd_spindle_decrease(const emcmot_command_t *c)
{
    return speed_step(c, -1);
}

/* SPINDLE_BRAKE_ENGAGE: brake on, spindle stopped. */
int mot_cmd_spindle_brake_engage(const emcmot_command_t *c)
{
    int n = mot_cmd_spindle(c, "Attempt to brake non-existent spindle");

    if (n < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    spindle_off(n);
    return EMCMOT_COMMAND_OK;
}

/* SPINDLE_BRAKE_RELEASE. */
int mot_cmd_spindle_brake_release(const emcmot_command_t *c)
{
    int n = mot_cmd_spindle(c, "Attempt to release brake of non-existent spindle");

    if (n < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->spindle[n].brake = 0;
    return EMCMOT_COMMAND_OK;
}

/* SPINDLE_ORIENT (M19): stop, then orient to an angle; the controller waits for is-oriented. */
int mot_cmd_spindle_orient(const emcmot_command_t *c)
{
    int n = mot_cmd_spindle(c, "Attempt to orient non-existent spindle");
    mot_spindle_t *s;

    if (n < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    s = &mot->spindle[n];
    spindle_off(n);
    s->brake = 0;
    s->orient_angle = c->orientation;
    s->orient_mode = c->orient_mode;
    s->orient_fault = 0;
    s->orient_state = ORIENT_IN_PROGRESS;
    return EMCMOT_COMMAND_OK;
}

/* SET_SPINDLE_PARAMS: speed limits (forward max/min, reverse max/min) and increment. */
int mot_cmd_set_spindle_params(const emcmot_command_t *c)
{
    int n = mot_cmd_spindle(c, "Attempt to configure non-existent spindle");
    mot_spindle_t *s;

    if (n < 0)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    s = &mot->spindle[n];
    s->max_pos_speed = c->max_pos_speed;
    s->min_pos_speed = c->min_pos_speed;
    s->max_neg_speed = c->max_neg_speed;
    s->min_neg_speed = c->min_neg_speed;
    if (c->spindle_increment > 0.0)
        s->increment = c->spindle_increment;
    return EMCMOT_COMMAND_OK;
}
