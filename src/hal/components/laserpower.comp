component laserpower "Scale laser power by actual/requested velocity; in vector mode ramp it along a move";
pin in bit enabled "FALSE turns the laser off (power 0)";
pin in bit raster_mode "TRUE: command-power is raster-power; FALSE: vector mode";
pin in float raster_power "Raster power in percent";
pin in float vector_power "Vector power in percent (for example from an M67 output)";
pin in float distance_to_go "Distance left in the current move (motion.distance-to-go)";
pin in float req_velocity "Requested velocity (motion.requested-vel)";
pin in float cur_velocity "Current velocity (motion.current-vel)";
pin in float min_power "power at 0 percent";
pin in float max_power "power at 100 percent and full velocity";
pin out float vel_scale "|cur-velocity| / |req-velocity|, 0 when either is 0";
pin out float start_power "Vector power when the current ramp started";
pin out float start_distance "distance-to-go when the current ramp started";
pin out float command_power "Commanded power in percent before velocity scaling";
pin out float power "(max-power - min-power) * vel-scale * command-power / 100 + min-power; 0 when off";
variable double prev_vector_power;
variable double prev_distance;
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """LinuxCNC's laserpower, with its memories kept per instance (LinuxCNC shares them
between instances). A value counts as zero below 0.00005 in magnitude.

In vector mode a new ramp starts when distance-to-go grows (a new move) or vector-power
changes by 0.00005 or more: start-power is the previous vector power and start-distance the
current distance-to-go. command-power then moves from start-power to vector-power as the
move is used up: start + (vector-power - start) * (1 - distance-to-go / start-distance);
where LinuxCNC divides 0 by 0 (start-distance 0) the ratio is taken as 0, so command-power
is vector-power.

power is 0 while enabled is FALSE or command-power is negative (or NaN); NaN or infinite
velocities give vel-scale 0.""";
;;
#define LP_ZERO 0.00005

FUNCTION(_)
{
    double req = fabs(req_velocity), cur = fabs(cur_velocity), ratio;
    vel_scale = (req < LP_ZERO || cur < LP_ZERO) ? 0.0 : cur / req;
    if (!(vel_scale - vel_scale == 0.0))  /* NaN or infinite velocities scale to 0 */
        vel_scale = 0.0;
    if (raster_mode) {
        command_power = raster_power;
    } else {
        if (prev_distance < distance_to_go || fabs(vector_power - prev_vector_power) >= LP_ZERO) {
            start_power = prev_vector_power;
            start_distance = distance_to_go;
        }
        prev_vector_power = vector_power;
        prev_distance = distance_to_go;
        ratio = fabs(start_distance) < LP_ZERO ? 0.0 : distance_to_go / start_distance;
        command_power = start_power + (vector_power - start_power) * (1.0 - ratio);
    }
    if (!enabled || !(command_power >= 0))  /* negative or NaN: off */
        power = 0;
    else
        power = (max_power - min_power) * vel_scale * command_power / 100.0 + min_power;
}
