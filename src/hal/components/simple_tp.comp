component simple_tp "Single-axis trapezoidal planner (the free-mode jog planner of motion)";
description "While enabled, current-pos moves to target-pos within maxvel and maxaccel; disabled, it decelerates to a stop.";
pin in float target_pos "Position to reach";
pin in float maxvel "Velocity limit";
pin in float maxaccel "Acceleration limit";
pin in bit enable "Plan toward target-pos";
pin out float current_pos "Planned position";
pin out float current_vel "Planned velocity";
pin out bit active "Moving, or about to";
function update;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
FUNCTION(update)
{
    double dv = maxaccel * fperiod, tiny = dv * fperiod * 0.001, vreq = 0, vel = current_vel;
    active = 0;
    if (enable) {
        double e = target_pos - current_pos;
        if (e > tiny) {
            vreq = -dv + sqrt(2 * maxaccel * e + dv * dv);
            active = 1;
        } else if (e < -tiny) {
            vreq = dv - sqrt(-2 * maxaccel * e + dv * dv);
            active = 1;
        }
    }
    if (vreq > maxvel) vreq = maxvel;
    if (vreq < -maxvel) vreq = -maxvel;
    if (vreq > vel + dv) vel += dv;
    else if (vreq < vel - dv) vel -= dv;
    else vel = vreq;
    if (vel != vel)
        vel = 0;  /* NaN limits: stop rather than spread NaN */
    current_vel = vel;
    if (vel != 0)
        active = 1;
    current_pos += vel * fperiod;
}
