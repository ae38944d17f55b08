/* mot_spindle.c: spindle inputs (feedback, at-speed, orient handshake) and outputs (speed after override and limits). */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"

#define ORIENT_IN_PROGRESS 1
#define ORIENT_COMPLETE 2
#define ORIENT_FAULTED 3

/* The orient handshake: is-oriented completes it, a non-zero orient-fault aborts it. */
static void orient_input(mot_spindle_t *s, const mot_spindle_pins_t *p)
{
    if (s->orient_state != ORIENT_IN_PROGRESS)
        return;
    if (*p->orient_fault != 0) {
        s->orient_fault = *p->orient_fault;
        s->orient_state = ORIENT_FAULTED;
        mot_report("fault %d during orient in progress", s->orient_fault);
    } else if (*p->is_oriented) {
        s->orient_state = ORIENT_COMPLETE;
        s->locked = 1;
        s->brake = 1;
    }
}

/* Read every spindle's inputs. */
void mot_spindle_inputs(void)
{
    for (int n = 0; n < mot->max_spindles; n++) {
        mot_spindle_t *s = &mot->spindle[n];
        const mot_spindle_pins_t *p = &mot->pins->spindle[n];
        double revs = *p->revs, speed = *p->speed_in;
        s->revs = isfinite(revs) ? revs : s->revs;
        s->speed_fb_rps = isfinite(speed) ? speed : s->speed_fb_rps;
        s->at_speed = *p->at_speed != 0;
        s->inhibit = *p->inhibit != 0;
        orient_input(s, p);
    }
}

/* Constant surface speed: rpm from the X distance to the spindle axis, capped by the S maximum. */
static double css_rpm(const mot_spindle_t *s)
{
    double radius = fabs(mot->carte_pos_cmd.tran.x - s->css_xoffset);
    double cap = fabs(s->speed);
    double rpm = radius > 0.0 ? s->css_factor / radius : cap;

    if (cap > 0.0 && rpm > cap)
        rpm = cap;
    return rpm * s->direction;
}

/* Speed after override, inhibit and the [SPINDLE_n] limits. */
static double speed_out(const mot_spindle_t *s)
{
    double v;

    if (!s->on)
        return 0.0;
    v = s->css_factor != 0.0 ? css_rpm(s) : s->speed;
    if (s->override_enabled)
        v *= s->scale;
    if (s->tap_reverse)
        v = -v;
    if (s->inhibit || !isfinite(v))
        return 0.0;
    if (v > 0.0) {
        v = fmin(v, s->max_pos_speed);
        v = fmax(v, s->min_pos_speed);
    } else if (v < 0.0) {
        v = fmax(v, s->max_neg_speed);
        v = fmin(v, s->min_neg_speed);
    }
    return v;
}

/* Write every spindle's output pins. */
void mot_spindle_outputs(void)
{
    for (int n = 0; n < mot->max_spindles; n++) {
        mot_spindle_t *s = &mot->spindle[n];
        mot_spindle_pins_t *p = &mot->pins->spindle[n];
        double v = n < mot->num_spindles ? speed_out(s) : 0.0;
        int dir = s->tap_reverse ? -s->direction : s->direction;
        s->speed_out = v;
        *p->speed_out = v;
        *p->speed_out_abs = fabs(v);
        *p->speed_out_rps = v / 60.0;
        *p->speed_out_rps_abs = fabs(v) / 60.0;
        *p->speed_cmd_rps = s->on ? s->speed / 60.0 : 0.0;
        *p->on = s->on;
        *p->forward = s->on && dir > 0;
        *p->reverse = s->on && dir < 0;
        *p->brake = s->brake;
        *p->orient = s->orient_state == ORIENT_IN_PROGRESS;
        *p->locked = s->locked;
        *p->orient_angle = s->orient_angle;
        *p->orient_mode = s->orient_mode;
    }
}
