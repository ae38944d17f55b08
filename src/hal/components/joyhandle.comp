component joyhandle "Nonlinear shaping of joystick axes: deadband, power curve, offset and scale";
pin in float in "Joystick axis value, normally -1 to 1";
pin out float out "Shaped value";
param rw float power = 2.0 "Exponent of the curve; 1 is linear; values below 1 are rewritten to 1";
param rw float deadband = 0. "Inputs with a magnitude up to this value give 0 (rewritten into 0..0.99)";
param rw float scale = 1. "Output magnitude at full deflection (without offset)";
param rw float offset = 0. "Added to the output magnitude at full deflection";
param rw bit inverse = 0 "TRUE mirrors the curve about the middle of the live range: steep near the deadband";
function _ "Compute the output";
license "GPL";
author "OpenEMC";
description """
LinuxCNC's joyhandle. power below 1 (or NaN) is rewritten to 1; deadband is held
within 0..0.99. With p = power - 1, a = -1/(deadband^p - 1) and b = 1 - a the
curve for deadband < x < 1 is scale * (a*x^power + b*x) + offset (linear
alin*x + clin through (deadband, 0) and (1, scale + offset) when power is 1);
|in| >= 1 gives +-(scale + offset), |in| <= deadband 0, NaN 0. Negative inputs
mirror positive ones. With inverse the curve is mirrored about its middle point
(xm, ym), xm = (deadband + 1)/2; for negative inputs this follows LinuxCNC,
which is not symmetric: with the defaults in = 0.5 gives 0.75 but -0.5 gives
-1.25.
""";
;;
#include "rtapi_math.h"

/* The curve's coefficients for the current params. */
typedef struct {
    double a, b, alin, clin, xm, ym;
} joy_curve_t;

/* Hold the params within LinuxCNC's limits (written back, as LinuxCNC does). */
static void joy_fix_params(struct __comp_state *__comp_inst)
{
    if (!(power >= 1.0)) power = 1.0;
    if (deadband >= 0.99) deadband = 0.99;
    if (!(deadband > 0.0)) deadband = 0.0;
}

static joy_curve_t joy_curve(struct __comp_state *__comp_inst)
{
    joy_curve_t c;
    double p = power - 1.0;
    c.a = -1.0 / (pow(deadband, p) - 1.0);
    c.b = 1.0 - c.a;
    c.alin = -scale / (deadband - 1.0);
    c.clin = scale + offset - c.alin;
    c.xm = (deadband + 1.0) / 2.0;
    c.ym = c.alin * c.xm + c.clin;
    return c;
}

/* The power curve at x in (deadband, 1). */
static double joy_power(struct __comp_state *__comp_inst, const joy_curve_t *c, double x)
{
    return scale * (c->a * pow(x, power) + c->b * x) + offset;
}

FUNCTION(_)
{
    joy_fix_params(__comp_inst);
    joy_curve_t c = joy_curve(__comp_inst);
    double x = in, m = fabs(x);
    if (x >= 1.0) {
        out = scale + offset;
    } else if (x >= -deadband && x <= deadband) {
        out = 0;
    } else if (x <= -1.0) {
        out = -scale - offset;
    } else if (x > deadband && x < 1.0 && power == 1.0) {
        out = c.alin * x + c.clin;
    } else if (x > deadband && x < 1.0) {
        out = inverse ? 2.0 * c.ym - joy_power(__comp_inst, &c, 2.0 * c.xm - x) : joy_power(__comp_inst, &c, x);
    } else if (x < -deadband && x > -1.0 && power == 1.0) {
        out = -(c.alin * m + c.clin);
    } else if (x < -deadband && x > -1.0) {
        out = inverse ? -2.0 * c.ym - joy_power(__comp_inst, &c, 2.0 * c.xm + x) : -joy_power(__comp_inst, &c, m);
    } else {
        out = 0;
    }
}
