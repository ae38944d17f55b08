component orient "Provide a PID command for spindle orientation from the spindle position, a target angle and a mode";
pin in bit enable "On its rising edge the command is computed; while TRUE poserr and is-oriented are updated";
pin in s32 mode "0: rotate the shortest way; 1: always rotate clockwise (position increasing); 2: always rotate counterclockwise (position decreasing)";
pin in float position "Spindle position in revolutions";
pin in float angle "Target angle in degrees, taken modulo 360";
pin out float command "Target spindle position in revolutions, for the PID command input";
pin out float poserr "Position error (command - position) in degrees, an aid for PID tuning";
pin out bit is_oriented "TRUE while enabled and |poserr| < tolerance";
pin in float tolerance = 0.5 "Tolerance in degrees for is-oriented";
variable int last_enable;
function _;
description """The target angle is measured from spindle position 0 (a whole number of
revolutions). On the rising edge of enable the component picks the position
nearest to the current one, in the direction given by mode, whose angle is the
target angle, and holds it on command until the next rising edge. A move is always
less than one revolution (at most half a revolution in mode 0). While enable is
FALSE, poserr and command keep their values and is-oriented is FALSE.""";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
double target, frac, delta;
if (enable && !last_enable) {
    target = fmod(angle, 360.0) / 360.0;
    if (target < 0) target += 1.0;
    frac = position - floor(position);
    delta = target - frac;
    if (mode == 1) {
        if (delta < 0) delta += 1.0;
    } else if (mode == 2) {
        if (delta > 0) delta -= 1.0;
    } else if (delta > 0.5) {
        delta -= 1.0;
    } else if (delta < -0.5) {
        delta += 1.0;
    }
    command = position + delta;
}
last_enable = enable;
if (enable) {
    poserr = (command - position) * 360.0;
    is_oriented = fabs(poserr) < tolerance;
} else {
    is_oriented = 0;
}
