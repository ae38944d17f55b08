component thcud "Torch height control driven by up/down signals from an external THC";
pin in bit torch-up "Raise request from the height controller";
pin in bit torch-down "Lower request from the height controller";
pin in float current-vel "Current velocity, connect to motion.current-vel";
pin in float requested-vel "Requested velocity, connect to motion.requested-vel";
pin in bit torch-on "Torch on, connect to the spindle on output";
pin in bit arc-ok "Arc OK from the plasma power source";
pin in bit enable "TRUE allows height corrections";
pin in float z-pos-in "Z motor position command from motion";
pin out float z-pos-out "Z motor position command with the height correction added";
pin out float z-fb-out "Z position feedback for motion (the command without the correction)";
pin out float cur-vel "Copy of current-vel";
pin out float req-vel "Copy of requested-vel";
pin out bit vel-status "TRUE while the machine runs within velocity-tol of the requested velocity";
pin out bit removing-offset "TRUE while the height correction is being taken back out";
param rw float velocity-tol "Allowed shortfall of current-vel below requested-vel, in percent";
param rw float correction-vel "Height change per servo period while correcting or removing the correction, in machine units";
variable double offset;
option singleton yes;
function _ "Update the height correction";
license "GPL";
author "OpenEMC";
description """
While enable, torch-on and arc-ok are TRUE and the machine is at cut speed
(vel-status), every period with torch-up adds correction-vel to the Z
correction and every period with torch-down subtracts it.  When any of those
conditions fails, corrections stop; when the torch is off or the component is
disabled the correction is taken back out at correction-vel per period (never
past zero).  z-pos-out = z-pos-in + correction; z-fb-out = z-pos-in, so motion
never sees a following error from the correction.
""";
;;
#include "rtapi_math.h"

/* TRUE when current velocity is within velocity-tol percent below the requested one. */
static int thcud_at_speed(double cur, double req, double tol_pct)
{
    return req > 0 && cur >= req * (1.0 - tol_pct / 100.0);
}

/* Move value towards zero by at most step. */
static double thcud_towards_zero(double value, double step)
{
    if (fabs(value) <= step) return 0.0;
    return value > 0 ? value - step : value + step;
}

/* Apply or remove the height correction and copy the velocities. */
FUNCTION(_)
{
    double step = correction_vel == correction_vel ? fabs(correction_vel) : 0.0;  /* NaN: no correction */
    int at_speed = thcud_at_speed(current_vel, requested_vel, velocity_tol);
    cur_vel = current_vel;
    req_vel = requested_vel;
    vel_status = at_speed;
    if (enable && torch_on) {
        removing_offset = 0;
        if (arc_ok && at_speed && torch_up && !torch_down) offset += step;
        if (arc_ok && at_speed && torch_down && !torch_up) offset -= step;
    } else {
        removing_offset = offset != 0.0;
        offset = thcud_towards_zero(offset, step);
    }
    z_pos_out = z_pos_in + offset;
    z_fb_out = z_pos_in;
}
