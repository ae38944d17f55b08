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
pin out float cur-offset "The height correction now applied";
pin out bit vel-status "TRUE while the machine runs within velocity-tol of the requested velocity";
pin out bit removing-offset "TRUE while the torch is off and a correction is left to take out";
pin in float correction-vel "Height change per servo period while correcting, in machine units";
param rw float velocity-tol "Allowed shortfall of current-vel below requested-vel, in percent";
variable double offset;
variable double last_z;
option singleton yes;
function _ "Update the height correction";
license "GPL";
author "OpenEMC";
description """
While enable, torch-on and arc-ok are TRUE and the machine is at cut speed
(vel-status), every period with torch-up adds correction-vel to the Z
correction and every period with torch-down subtracts it.  While enabled with the
torch off, the correction is taken out as Z moves up, never faster than Z moves
and never past zero.  Disabled, the correction is dropped and Z passes through.
z-pos-out = z-pos-in + correction; z-fb-out = z-pos-in, so motion never sees a
following error from the correction.
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

/* Apply, take out or drop the height correction. */
FUNCTION(_)
{
    double step = correction_vel == correction_vel ? fabs(correction_vel) : 0.0;  /* NaN: no correction */
    double dz = z_pos_in - last_z;
    vel_status = thcud_at_speed(current_vel, requested_vel, velocity_tol);
    last_z = z_pos_in;
    if (!enable) {
        offset = 0.0;
    } else if (torch_on) {
        if (arc_ok && vel_status && torch_up && !torch_down) offset += step;
        if (arc_ok && vel_status && torch_down && !torch_up) offset -= step;
    } else if (dz > 0) {
        offset = thcud_towards_zero(offset, dz);
    }
    removing_offset = enable && !torch_on && offset != 0.0;
    cur_offset = offset;
    z_pos_out = z_pos_in + offset;
    z_fb_out = z_pos_in;
}
