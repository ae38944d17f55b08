component sim_spindle "Simulated spindle with index pulse";
pin in float velocity_cmd "Commanded speed in revolutions per second (times scale)";
pin out float position_fb "Position in revolutions";
pin io bit index_enable "When TRUE, the next whole revolution zeroes the position and clears this pin";
param rw float scale = 1.0 "velocity-cmd units per revolution per second";
variable double pos;
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
double sc = scale, old = pos, step;
if (sc == 0.0) sc = 1.0;
step = velocity_cmd / sc * fperiod;
if (isfinite(step)) pos += step;  /* a NaN or infinite command does not move the spindle */
if (index_enable && floor(pos) != floor(old)) {
    pos -= pos > old ? floor(pos) : ceil(pos);
    index_enable = 0;
}
position_fb = pos;
