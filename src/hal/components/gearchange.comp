component gearchange "Select between two spindle gear ranges";
pin in bit sel "Gear selection: FALSE = gear 1, TRUE = gear 2";
pin in float speed-in "Commanded spindle speed";
pin out float speed-out "Motor speed for the selected gear, limited to its range";
pin in bit dir-in "Commanded direction";
pin out bit dir-out "Direction for the motor, inverted in gear 2 when reverse is TRUE";
param rw float min1 = 0 "Lowest speed gear 1 can run at";
param rw float max1 = 100000 "Highest speed gear 1 can run at";
param rw float min2 = 0 "Lowest speed gear 2 can run at";
param rw float max2 = 100000 "Highest speed gear 2 can run at";
param rw float scale2 = 1.0 "Ratio of spindle speed to motor speed in gear 2 relative to gear 1; gear 2 is the high gear, so values below 1 are reset to 1";
param rw bit reverse = 0 "TRUE when gear 2 turns the spindle the other way, so the motor direction must be inverted";
function _ "Compute speed-out and dir-out";
license "GPL";
author "OpenEMC";
description """
The magnitude of speed-in is limited to min1..max1 (gear 1) or min2..max2
(gear 2); a zero command stays zero so a stopped spindle stays stopped.  In
gear 2 the limited speed is divided by scale2.  The sign of speed-in is kept.
""";
;;
#include "rtapi_math.h"

/* Limit a nonzero magnitude to lo..hi; zero means stopped and stays zero. */
static double gear_limit(double mag, double lo, double hi)
{
    if (mag == 0.0) return 0.0;
    if (mag > hi) mag = hi;
    if (mag < lo) mag = lo;
    return mag;
}

/* Limit the speed to the selected gear, scale it for gear 2 and set the direction. */
FUNCTION(_)
{
    double mag = fabs(speed_in);
    if (scale2 < 1.0) scale2 = 1.0;
    if (sel) {
        mag = gear_limit(mag, min2, max2) / scale2;
        dir_out = reverse ? !dir_in : dir_in;
    } else {
        mag = gear_limit(mag, min1, max1);
        dir_out = dir_in;
    }
    speed_out = speed_in < 0 ? -mag : mag;
}
