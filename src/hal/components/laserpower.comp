component laserpower "Scale laser power with the actual feed velocity so each unit of length gets the same energy";
pin in bit enable "TRUE: scale req-power by velocity; FALSE: output is req-power unchanged";
pin in float req_power "Requested laser power (for example the spindle speed command)";
pin in float req_vel "Requested (programmed) feed velocity, for example motion.requested-vel";
pin in float cur_vel "Actual feed velocity, for example motion.current-vel";
pin in float min_power = 0 "Least power given while scaling and the laser is on";
pin in float max_power = 100 "Most power ever given while scaling";
pin out float output "Laser power to apply";
function _ "Compute the output power";
description """
While enable is TRUE the requested power is multiplied by the ratio of the
actual to the requested velocity (absolute value of cur-vel divided by
req-vel), so the laser dims while the machine accelerates or slows down for a
corner and the burn stays even. The ratio never exceeds 1, so the output never
goes above the requested power; when req-vel is 0 or less (a dwell, or no feed
move) the ratio is taken as 1. The result is then limited to min-power ... max-power
(max-power wins if the two cross). A requested power of 0 or less means the
laser is off: the output is 0 and min-power does not apply.

While enable is FALSE the output simply follows req-power, without scaling or
limits.
""";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
/* Velocity ratio actual/requested, in 0..1; 1 without a requested velocity. */
static double velocity_ratio(double requested, double actual)
{
    double ratio;
    if (!(requested > 0)) return 1.0;
    ratio = fabs(actual) / requested;
    if (ratio != ratio) return 0.0;  /* NaN velocity: laser off */
    return ratio > 1.0 ? 1.0 : ratio;
}

/* Scale the requested power by velocity and limit it; pass it through when disabled. */
FUNCTION(_)
{
    double power;
    if (!enable) {
        output = req_power;
        return;
    }
    if (!(req_power > 0)) {
        output = 0;
        return;
    }
    power = req_power * velocity_ratio(req_vel, cur_vel);
    if (power < min_power) power = min_power;
    if (power > max_power) power = max_power;
    output = power;
}
