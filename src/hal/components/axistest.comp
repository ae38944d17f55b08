component axistest "Drive one axis for PnCconf tuning: jog, or run back and forth with a pause at each end";
pin in bit jog_minus "Jog in the negative direction";
pin in bit jog_plus "Jog in the positive direction";
pin in bit run "Run back and forth";
pin in float maxvel "Velocity limit (jogging)";
pin in float amplitude "Distance of each end from the start";
pin in s32 dir "0 both ways, 1 only up, 2 only down";
pin in float position_fb "Position feedback";
pin out float position_cmd "Position command";
pin out bit running "A run is in progress";
pin out float run_target "Unused";
pin out float run_start "Where the run started";
pin out float run_low "Lower end of the run";
pin out float run_high "Upper end of the run";
pin in s32 pause "Seconds to wait at each end";
param r float elapsed "Time spent at the current end, seconds";
param rw float epsilon = 0.001 "Arrival tolerance";
variable int timer_running;
variable double timer;
function update;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
#include "hal/components/axis_tester.h"

FUNCTION(update)
{
    if (!axis_test_step(__comp_inst, fperiod))
        return;
    if (jog_minus)
        position_cmd = position_fb - 10;
    else if (jog_plus)
        position_cmd = position_fb + 10;
    else
        position_cmd = position_fb;
}
