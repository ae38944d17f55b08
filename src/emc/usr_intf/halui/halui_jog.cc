// halui_jog.cc: joint and axis selection, homing buttons and jogging (plus/minus, increments, analog) from halui's pins.
#include <cmath>

#include "halui.hh"

namespace {

// Jog speeds on the pins are machine units per minute; NML jogs take units per second.
const double SECONDS_PER_MINUTE = 60.0;

// Jogs reach motion only in the matching motion mode with the machine on: joint jogs in
// free (joint) mode, axis jogs in teleop mode. Anything else would be refused by motion.
bool jog_allowed(Halui &h, bool axis)
{
    if (!halui_machine_ready(h)) return false;
    const EMC_STAT &s = h.client.status();
    if (s.task.state != EMC_TASK_STATE_ON) return false;
    return s.motion.traj.mode == (axis ? EMC_TRAJ_MODE_TELEOP : EMC_TRAJ_MODE_FREE);
}

// jjogmode of an axis or joint jog.
int jog_mode(bool axis)
{
    return axis ? EMC_JOG_AXIS : EMC_JOG_JOINT;
}

// Jog continuously at speed_per_min (its sign is the direction).
void jog_cont(Halui &h, int n, bool axis, double speed_per_min)
{
    if (!jog_allowed(h, axis) || speed_per_min == 0) return;
    EMC_JOG_CONT m;
    m.joint_or_axis = n;
    m.jjogmode = jog_mode(axis);
    m.vel = speed_per_min / SECONDS_PER_MINUTE;
    halui_send(h, m);
}

// Stop a jog.
void jog_stop(Halui &h, int n, bool axis)
{
    if (!jog_allowed(h, axis)) return;
    EMC_JOG_STOP m;
    m.joint_or_axis = n;
    m.jjogmode = jog_mode(axis);
    halui_send(h, m);
}

// An increment of |incr|; the sign of speed gives the direction (as motion reads it).
void jog_incr(Halui &h, int n, bool axis, double speed_per_min, double incr)
{
    if (!jog_allowed(h, axis) || speed_per_min == 0 || incr == 0) return;
    EMC_JOG_INCR m;
    m.joint_or_axis = n;
    m.jjogmode = jog_mode(axis);
    m.vel = speed_per_min / SECONDS_PER_MINUTE;
    m.incr = std::fabs(incr);
    halui_send(h, m);
}

// An analog input jogs at speed * value while |value| is at least the deadband.
void analog_jog(Halui &h, int n, bool axis, double speed, double deadband, double value, AnalogJog &a)
{
    double v = std::fabs(value) < deadband ? 0.0 : value;
    double vel = speed * v;
    if (!std::isfinite(vel) || vel == a.last) return;
    a.last = vel;
    if (vel == 0) jog_stop(h, n, axis);
    else jog_cont(h, n, axis, vel);
}

// The plus/minus, increment and analog controls of one joint or axis.
void jog_controls(Halui &h, JogPins &p, int n, bool axis, double speed, double deadband, AnalogJog *a)
{
    int e = p.plus.edge();
    if (e > 0) jog_cont(h, n, axis, speed);
    else if (e < 0) jog_stop(h, n, axis);
    e = p.minus.edge();
    if (e > 0) jog_cont(h, n, axis, -speed);
    else if (e < 0) jog_stop(h, n, axis);
    if (p.increment_plus.rose()) jog_incr(h, n, axis, speed, **p.increment);
    if (p.increment_minus.rose()) jog_incr(h, n, axis, -speed, **p.increment);
    if (a && p.analog) analog_jog(h, n, axis, speed, deadband, **p.analog, *a);
}

// A joint command (home, unhome) for one joint.
template <class M>
void joint_cmd(Halui &h, int joint)
{
    M m;
    m.joint = joint;
    halui_send(h, m);
}

// Joint buttons: select, home, unhome, jogs; then the selected joint's.
void joints(Halui &h)
{
    HaluiPins &p = h.pins;
    double speed = **p.joint_jog_speed;
    double deadband = **p.joint_jog_deadband;
    for (int j = 0; j < h.cfg.joints; j++) {
        JointPins &jp = p.joint[j];
        if (jp.select.rose()) h.selected_joint = j;
        if (jp.home.rose()) joint_cmd<EMC_JOINT_HOME>(h, j);
        if (jp.unhome.rose()) joint_cmd<EMC_JOINT_UNHOME>(h, j);
        jog_controls(h, jp.jog, j, false, speed, deadband, &h.joint_analog[j]);
    }
    if (p.joint_selected_home.rose()) joint_cmd<EMC_JOINT_HOME>(h, h.selected_joint);
    if (p.joint_selected_unhome.rose()) joint_cmd<EMC_JOINT_UNHOME>(h, h.selected_joint);
    jog_controls(h, p.joint_selected_jog, h.selected_joint, false, speed, 0, nullptr);
}

// Axis buttons: select and jogs of the configured axes; then the selected axis's.
void axes(Halui &h)
{
    HaluiPins &p = h.pins;
    double deadband = **p.axis_jog_deadband;
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        if (!(h.cfg.axis_mask & (1u << a))) continue;
        AxisPins &ap = p.axis[a];
        if (ap.select.rose()) h.selected_axis = a;
        jog_controls(h, ap.jog, a, true, halui_axis_jog_speed(h, a), deadband, &h.axis_analog[a]);
    }
    jog_controls(h, p.axis_selected_jog, h.selected_axis, true, halui_axis_jog_speed(h, h.selected_axis),
                 0, nullptr);
}

} // namespace

// Linear axes use halui.axis.jog-speed, A/B/C halui.axis.jog-speed-angular (or the linear
// speed while that is 0); the GUI bridge may have overridden either.
double halui_axis_jog_speed(const Halui &h, int axis)
{
    bool angular = axis >= 3 && axis <= 5;
    if (!angular) return h.gui_rate.rate;
    return h.gui_rate.rate_ang != 0 ? h.gui_rate.rate_ang : h.gui_rate.rate;
}

// Selection, homing and jogging of this cycle.
void halui_jogging(Halui &h)
{
    joints(h);
    axes(h);
}
