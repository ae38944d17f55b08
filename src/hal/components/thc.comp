component thc "Torch height control from a THCAD voltage-to-frequency card read through an encoder velocity";
description """
The arc voltage is (encoder-vel - scale-offset) x vel-scale.  While enabled, the torch is on,
the arc is OK and the machine moves at least velocity-tol percent below the requested
velocity, the Z offset moves by correction-vel per period to bring the voltage within
voltage-tol of volts-requested.  With the torch off, upward Z moves take the offset back out.
""";
pin in float encoder_vel "Encoder velocity of the THCAD frequency";
pin out float volts "Arc voltage";
pin in bit enable "Torch height control on";
pin in float z_pos_in "Z position command from motion";
pin out float z_pos_out "Z position command with the offset";
pin out float z_fb_out "Z feedback to motion (without the offset)";
pin in float volts_requested "Arc voltage to hold";
pin in float vel_tol "Unused (see the velocity-tol param)";
pin in bit torch_on "Torch is on";
pin in bit arc_ok "Arc is established";
pin out float offset_value "Current Z offset";
pin in float requested_vel "Requested velocity";
pin in float current_vel "Current velocity";
pin out bit vel_status "At speed";
param rw float vel_scale "Volts per unit of encoder velocity";
param rw float scale_offset "Encoder velocity at 0 V";
param rw float velocity_tol "Percent below the requested velocity still counted as at speed";
param rw float voltage_tol "Dead band in volts";
param rw float correction_vel "Offset change per period, machine units";
variable double offset;
variable double last_z;
option singleton yes;
function _;
license "GPL";
author "OpenEMC";
;;
double v = (encoder_vel - scale_offset) * vel_scale;
volts = v > 0 ? v : 0;
offset_value = offset;
if (!enable) {
    z_pos_out = z_pos_in;
    z_fb_out = z_pos_in;
    return;
}
vel_status = current_vel > 0 && current_vel >= requested_vel * (1 - velocity_tol / 100);
if (torch_on && arc_ok && vel_status) {
    if (volts + voltage_tol > volts_requested)
        offset -= correction_vel;
    if (volts - voltage_tol < volts_requested)
        offset += correction_vel;
    last_z = 0;
}
if (!torch_on) {
    double dz = z_pos_in - last_z;
    if (dz > 0 && offset != 0) {
        if (offset > 0)
            offset = dz >= offset ? 0 : offset - dz;
        else
            offset += dz;  /* may pass 0, as LinuxCNC does */
    }
    last_z = z_pos_in;
}
z_pos_out = z_pos_in + offset;
z_fb_out = z_pos_in;
