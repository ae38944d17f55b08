/* spindle.c: open-loop spindle speed control with per-gear limits, acceleration, deceleration, output
 * scaling and an optional simulated encoder (not motion's spindle.N pins). */
#include <stddef.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "rtapi_math.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Spindle speed control with gears, acceleration and deceleration limits");

#define SPINDLE_MAX_GEARS 16
#define SPINDLE_MAX_INST 16

static int count;
RTAPI_MP_INT(count, "number of instances");
static char *names = "";
RTAPI_MP_STRING(names, "names of the instances");
static int numgears[SPINDLE_MAX_INST] = { 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1 };
RTAPI_MP_ARRAY_INT(numgears, SPINDLE_MAX_INST, "gears of each instance (1..16)");

/* Pins of one gear. */
typedef struct {
    hal_float_t *scale, *min, *max, *accel, *decel, *speed_tol, *zero_tol, *offset;
    hal_bit_t *select;
} spindle_gear_t;

/* One spindle. */
typedef struct {
    hal_float_t *commanded, *actual, *lpf, *rpm, *rpm_abs, *output;
    hal_bit_t *enable, *simulate, *at_speed, *zero_speed, *limited, *forward, *reverse, *brake;
    hal_u32_t *select_gear, *current_gear;
    int ngears;
    spindle_gear_t gear[SPINDLE_MAX_GEARS];
} spindle_t;

#define SP(sfx, t, d, f, v) { sfx, t, d, offsetof(spindle_t, f), v }
static const comp_pin_def_t spindle_pins[] = {
    SP(".commanded-speed", HAL_FLOAT, HAL_IN, commanded, 0),
    SP(".actual-speed", HAL_FLOAT, HAL_IN, actual, 0),
    SP(".simulate-encoder", HAL_BIT, HAL_IN, simulate, 0),
    SP(".enable", HAL_BIT, HAL_IN, enable, 0),
    SP(".spindle-lpf", HAL_FLOAT, HAL_IN, lpf, 0),
    SP(".select-gear", HAL_U32, HAL_IN, select_gear, 0),
    SP(".current-gear", HAL_U32, HAL_OUT, current_gear, 0),
    SP(".spindle-rpm", HAL_FLOAT, HAL_OUT, rpm, 0),
    SP(".spindle-rpm-abs", HAL_FLOAT, HAL_OUT, rpm_abs, 0),
    SP(".at-speed", HAL_BIT, HAL_OUT, at_speed, 0),
    SP(".zero-speed", HAL_BIT, HAL_OUT, zero_speed, 0),
    SP(".limited", HAL_BIT, HAL_OUT, limited, 0),
    SP(".forward", HAL_BIT, HAL_OUT, forward, 0),
    SP(".reverse", HAL_BIT, HAL_OUT, reverse, 0),
    SP(".brake", HAL_BIT, HAL_OUT, brake, 0),
    SP(".output", HAL_FLOAT, HAL_OUT, output, 0),
};

#define GP(sfx, t, f, v) { sfx, t, HAL_IN, offsetof(spindle_gear_t, f), v }
static const comp_pin_def_t gear_pins[] = {
    GP(".scale", HAL_FLOAT, scale, 1.0), GP(".min", HAL_FLOAT, min, 0), GP(".max", HAL_FLOAT, max, 0),
    GP(".accel", HAL_FLOAT, accel, 0), GP(".decel", HAL_FLOAT, decel, 0),
    GP(".speed-tolerance", HAL_FLOAT, speed_tol, 20), GP(".zero-tolerance", HAL_FLOAT, zero_tol, 20),
    GP(".offset", HAL_FLOAT, offset, 0), GP(".select", HAL_BIT, select, 0),
};

/* The gear in use: select-gear when non-zero (at most the last gear), else the highest selected one. */
static const spindle_gear_t *spindle_gear(spindle_t *s)
{
    int g = 0;
    if (*s->select_gear) {
        g = *s->select_gear > 15 ? 15 : (int)*s->select_gear;
        if (g >= s->ngears)
            g = s->ngears - 1; /* LinuxCNC reads a gear that has no pins here */
        *s->current_gear = g;
        return &s->gear[g];
    }
    for (int i = 0; i < s->ngears; i++)
        if (*s->gear[i].select)
            g = i;
    *s->current_gear = 0;
    return &s->gear[g];
}

/* Clamp the command to the gear's min and max speeds (0 stays 0); sets limited. */
static double spindle_clamp(spindle_t *s, const spindle_gear_t *g, double cmd)
{
    int lim = 0;
    if (*g->min > 0 && cmd != 0 && fabs(cmd) < *g->min) {
        cmd = cmd > 0 ? *g->min : -*g->min;
        lim = 1;
    }
    if (*g->max > 0 && fabs(cmd) > *g->max) {
        cmd = cmd > 0 ? *g->max : -*g->max;
        lim = 1;
    }
    *s->limited = lim;
    return cmd;
}

/* Speed step toward cmd: never across zero, at most accel up and decel down (per call, or per
 * second in simulation). */
static double spindle_step(const spindle_gear_t *g, double cmd, double cur, int reversing, double scale_t)
{
    double diff = cmd - cur;
    if (cur > 0 && diff < -cur) diff = -cur;
    if (cur < 0 && diff > -cur) diff = -cur;
    if (!reversing && *g->accel > 0) {
        double a = *g->accel * scale_t;
        if (cmd > 0 && diff > a) diff = a;
        if (cmd < 0 && diff < -a) diff = -a;
    }
    if (*g->decel > 0) {
        double d = *g->decel * scale_t;
        if (reversing) {
            if (cmd >= 0 && diff > d) diff = d;
            if (cmd <= 0 && diff < -d) diff = -d;
        } else {
            if (cmd >= 0 && diff < -d) diff = -d;
            if (cmd <= 0 && diff > d) diff = d;
        }
    }
    return diff;
}

/* Funct <prefix>: one control step. */
static void spindle_update(void *arg, long period)
{
    spindle_t *s = arg;
    double T = period * 1e-9;
    const spindle_gear_t *g = spindle_gear(s);
    if (!*s->simulate)
        *s->rpm = *s->actual * 60.0;
    double cur = *s->rpm, cmd = *s->enable ? *s->commanded : 0.0;
    *s->zero_speed = fabs(cur) <= *g->zero_tol;
    if (*s->lpf > 0 && *s->at_speed)
        *s->rpm_abs += (fabs(cur) - *s->rpm_abs) * *s->lpf * T;
    else
        *s->rpm_abs = fabs(cur);
    int reversing = (cmd > 0 && cur < 0) || (cmd < 0 && cur > 0);
    *s->at_speed = *g->speed_tol > 0 && fabs(cmd - cur) <= *g->speed_tol && !reversing;
    cmd = spindle_clamp(s, g, cmd);
    double diff = spindle_step(g, cmd, cur, reversing, *s->simulate ? T : 1.0);
    cur = *s->at_speed ? cmd : cur + diff;
    if (*s->simulate)
        *s->rpm = cur;
    if (cmd != 0) {
        *s->forward = cur > 0;
        *s->reverse = cur < 0;
    } else {
        int fwd = *s->forward;
        *s->forward = cur > 0 && fwd;
        *s->reverse = cur < 0 && fwd; /* LinuxCNC tests forward here too */
    }
    *s->output = (fabs(cur) + *g->offset) * *g->scale;
}

/* Create the pins and funct of instance i (numgears[i] gears). */
static int spindle_make(int comp_id, int i, const char *prefix)
{
    char name[HAL_NAME_LEN + 1];
    spindle_t *s = hal_malloc(sizeof(*s));
    if (!s) return -ENOMEM;
    memset(s, 0, sizeof(*s));
    s->ngears = i < SPINDLE_MAX_INST ? numgears[i] : 1;
    if (s->ngears < 1 || s->ngears > SPINDLE_MAX_GEARS) {
        rtapi_print_msg(RTAPI_MSG_ERR, "Number of gears is out of range\n");
        return -EINVAL;
    }
    int r = comp_pin_table(comp_id, s, spindle_pins, (int)(sizeof(spindle_pins) / sizeof(spindle_pins[0])),
                           prefix);
    for (int g = 0; g < s->ngears && r == 0; g++) {
        for (int k = 0; k < (int)(sizeof(gear_pins) / sizeof(gear_pins[0])) && r == 0; k++) {
            rtapi_snprintf(name, sizeof(name), "%s%s", prefix, gear_pins[k].suffix);
            comp_pin_def_t one = gear_pins[k];
            char sfx[24];
            rtapi_snprintf(sfx, sizeof(sfx), ".%d", g);
            one.suffix = sfx;
            r = comp_pin_table(comp_id, &s->gear[g], &one, 1, name);
        }
    }
    if (r) return r;
    if (s->ngears == 1)
        *s->gear[0].select = 1;
    return hal_export_funct(prefix, spindle_update, s, 1, 0, comp_id);
}

/* Create the instances (count= or names=, one by default). */
int rtapi_app_main(void)
{
    return comp_setup_named("spindle", "spindle", count, names, 1, spindle_make);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
