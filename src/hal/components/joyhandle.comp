component joyhandle "Nonlinear shaping of joystick axes: deadband, power curve, offset and scale";
pin in float in "Joystick axis value, normally -1 to 1";
pin out float out "Shaped value";
param rw float power = 2.0 "Exponent of the curve; 1 is linear, larger values give finer control near the centre; negative values act as 1";
param rw float deadband = 0. "Inputs with a magnitude up to this value give 0";
param rw float scale = 1. "Output magnitude at full deflection";
param rw float offset = 0. "Fraction of scale output just outside the deadband, so motion starts at a usable speed";
param rw bit inverse = 0 "TRUE mirrors the curve: steep near the deadband and flat near full deflection";
param rw bit clamp = 0 "TRUE limits the input magnitude to 1, so the output never exceeds scale";
function _ "Compute the output";
license "GPL";
author "OpenEMC";
description """
For an input magnitude above deadband, the distance past the deadband is
normalised to x = (|in| - deadband) / (1 - deadband), shaped as x^power
(or 1 - (1 - x)^power with inverse) and then
out = sign(in) * scale * (offset + (1 - offset) * shaped).
Inside the deadband out is 0.  A deadband of 1 or more always gives 0.
""";
;;
#include "rtapi_math.h"

/* x^p that keeps the sign of x, so a value past full deflection stays finite. */
static double joy_signed_pow(double x, double p)
{
    return x < 0 ? -pow(-x, p) : pow(x, p);
}

/* Shape the joystick input: deadband, normalise, power curve, offset, scale. */
FUNCTION(_)
{
    double mag = fabs(in), db = deadband > 0 ? deadband : 0, p = power < 0 ? 1.0 : power, x, shaped;
    if (clamp && mag > 1.0) mag = 1.0;
    if (mag <= db || db >= 1.0) {
        out = 0;
        return;
    }
    x = (mag - db) / (1.0 - db);
    shaped = inverse ? 1.0 - joy_signed_pow(1.0 - x, p) : joy_signed_pow(x, p);
    shaped = scale * (offset + (1.0 - offset) * shaped);
    out = in < 0 ? -shaped : shaped;
}
