component orient "Provide a PID command for spindle orientation from the spindle position, a target angle and a mode";
pin in bit enable "On its rising edge the command is computed; while TRUE poserr and is-oriented are updated";
pin in s32 mode "0: rotate the shortest way; 1: always rotate clockwise (position increasing); 2: always rotate counterclockwise (position decreasing)";
pin in float position "Spindle position in revolutions";
pin in float angle "Target angle in degrees";
pin out float command "Target spindle position in revolutions, for the PID command input";
pin out float poserr "Position error (position - command) in degrees, an aid for PID tuning";
pin out bit is_oriented "TRUE once the error has been within tolerance for more than 100 periods of this orientation";
pin in float tolerance = 0.5 "Tolerance in degrees for is-oriented";
variable int last_enable;
variable int debounce;
function _;
description """LinuxCNC's orient. The target angle is measured from spindle position 0 (a
whole number of revolutions). On the rising edge of enable the position is latched and
command is set, with a = angle/360, to floor(position + 0.5 - a) + a in mode 0 (nearest),
ceil(position - a) + a in mode 1 (position increasing) or floor(position - a) + a in
mode 2 (position decreasing); another mode leaves command as it was. While enable is TRUE,
poserr is (position - command) * 360 degrees, and every period with |poserr| below
tolerance counts (the count is not reset when the error grows again); is-oriented is TRUE
once more than 100 periods of this orientation were in tolerance. While enable is FALSE,
command and poserr keep their values and is-oriented is FALSE.""";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
#define ORIENT_DEBOUNCE 100

FUNCTION(_)
{
    is_oriented = 0;
    if (enable) {
        if (!last_enable) {
            double p = position, a = angle / 360.0;
            debounce = 0;
            if (mode == 0) command = floor(p + 0.5 - a) + a;
            else if (mode == 1) command = ceil(p - a) + a;
            else if (mode == 2) command = floor(p - a) + a;
        }
        poserr = (position - command) * 360.0;
        if (fabs(poserr) < tolerance && debounce <= ORIENT_DEBOUNCE) debounce++;
        is_oriented = debounce > ORIENT_DEBOUNCE;
    }
    last_enable = enable;
}
