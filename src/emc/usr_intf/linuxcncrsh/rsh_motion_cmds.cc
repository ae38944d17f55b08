// rsh_motion_cmds.cc: linuxcncrsh subcommands for positions, joints and axes: position reports, joint state, homing, jogging, heartbeat waits.
#include <algorithm>
#include <cerrno>
#include <cmath>

#include "rsh.hh"
#include "rsh_format.hh"
#include "ui_pose.hh"

namespace {

using R = RshResult;

const char AXIS_LETTERS[] = "XYZABCUVW";
// Jog speeds are machine units per minute; NML jogs take units per second.
const double SECONDS_PER_MINUTE = 60.0;
// Default and longest waits of joint_wait_homed / wait_heartbeat.
const double HOMED_WAIT_S = 10.0;
const double HEARTBEAT_WAIT_S = 1.0;

// Joints listed when no joint is named: at least six, as LinuxCNC always listed.
int joint_count(const EMC_STAT &st)
{
    return std::min(EMCMOT_MAX_JOINTS, std::max(6, st.motion.traj.joints));
}

// Axes listed when none is named: X..C, and U V W when the machine has one of them.
int axis_count(const EMC_STAT &st)
{
    return (st.motion.traj.axis_mask & 0x1c0) ? EMCMOT_MAX_AXIS : 6;
}

// Optional joint argument i (default dflt); -2 allowed only when allow_volatile.
R joint_arg(RshSession &s, const RshArgs &a, size_t i, long dflt, bool allow_volatile, int *joint)
{
    long v = dflt;
    long lowest = allow_volatile ? -2 : -1;
    if (a.count() > i && (!rsh_parse_int(a.at(i), &v) || v < lowest || v >= EMCMOT_MAX_JOINTS)) {
        s.reply("error: invalid joint: " + a.at(i) + " (valid: " + std::to_string(lowest) + " - " +
                std::to_string(EMCMOT_MAX_JOINTS - 1) + ")");
        return R::replied;
    }
    *joint = static_cast<int>(v);
    return R::ok;
}

// Optional axis argument (letter or index, default -1 = all).
R axis_arg(RshSession &s, const RshArgs &a, int *axis)
{
    *axis = a.count() >= 1 ? rsh_parse_axis(a.at(0)) : -1;
    if (*axis == -2) {
        s.reply("error: invalid axis: " + a.at(0) + " (valid: XYZABCUVW, 0 - 8 or -1)");
        return R::replied;
    }
    return R::ok;
}

// "<NAME> v0 v1 ..." for all axes, or "<NAME> <letter> v" for one.
R axis_values(RshServer &sv, RshSession &s, const RshArgs &a, const char *name,
              void (*values)(const EMC_STAT &, double *))
{
    const EMC_STAT *st = rsh_status(sv, s);
    int axis;
    if (!st) return R::nak;
    R r = axis_arg(s, a, &axis);
    if (r != R::ok) return r;
    double v[EMCMOT_MAX_AXIS];
    values(*st, v);
    std::string line = name;
    if (axis >= 0) line += std::string(" ") + AXIS_LETTERS[axis] + " " + rsh_real(v[axis]);
    for (int i = 0; axis < 0 && i < axis_count(*st); i++) line += " " + rsh_real(v[i]);
    s.reply(line);
    return R::ok;
}

// Per-axis values of the position reports: commanded and actual position in machine
// coordinates, the same in the current coordinate system.
void abs_cmd(const EMC_STAT &st, double *v)
{
    for (int i = 0; i < EMCMOT_MAX_AXIS; i++) v[i] = ui_pose_at(st.motion.traj.position, i);
}
void abs_act(const EMC_STAT &st, double *v)
{
    for (int i = 0; i < EMCMOT_MAX_AXIS; i++) v[i] = ui_pose_at(st.motion.traj.actualPosition, i);
}
void rel_cmd(const EMC_STAT &st, double *v) { ui_relative_position(st.task, st.motion.traj.position, v); }
void rel_act(const EMC_STAT &st, double *v) { ui_relative_position(st.task, st.motion.traj.actualPosition, v); }
// The work offset of each axis: G5x plus G92.
void pos_offset(const EMC_STAT &st, double *v)
{
    for (int i = 0; i < EMCMOT_MAX_AXIS; i++)
        v[i] = ui_pose_at(st.task.g5x_offset, i) + ui_pose_at(st.task.g92_offset, i);
}
// Velocity of each axis.
void axis_velocity(const EMC_STAT &st, double *v)
{
    for (int i = 0; i < EMCMOT_MAX_AXIS; i++) v[i] = st.motion.axis[i].velocity;
}

// The position reports.
R get_abs_cmd_pos(RshServer &sv, RshSession &s, const RshArgs &a) { return axis_values(sv, s, a, "ABS_CMD_POS", abs_cmd); }
R get_abs_act_pos(RshServer &sv, RshSession &s, const RshArgs &a) { return axis_values(sv, s, a, "ABS_ACT_POS", abs_act); }
R get_rel_cmd_pos(RshServer &sv, RshSession &s, const RshArgs &a) { return axis_values(sv, s, a, "REL_CMD_POS", rel_cmd); }
R get_rel_act_pos(RshServer &sv, RshSession &s, const RshArgs &a) { return axis_values(sv, s, a, "REL_ACT_POS", rel_act); }
R get_pos_offset(RshServer &sv, RshSession &s, const RshArgs &a) { return axis_values(sv, s, a, "POS_OFFSET", pos_offset); }
R get_axis_velocity(RshServer &sv, RshSession &s, const RshArgs &a) { return axis_values(sv, s, a, "AXIS_VELOCITY", axis_velocity); }

// "<NAME> w0 w1 ..." for all joints, or "<NAME> j w" for one; word() describes a joint.
R joint_words(RshServer &sv, RshSession &s, const RshArgs &a, const char *name,
              std::string (*word)(const EMC_JOINT_STAT &))
{
    const EMC_STAT *st = rsh_status(sv, s);
    int joint;
    if (!st) return R::nak;
    R r = joint_arg(s, a, 0, -1, false, &joint);
    if (r != R::ok) return r;
    std::string line = name;
    if (joint >= 0) line += " " + std::to_string(joint) + " " + word(st->motion.joint[joint]);
    for (int j = 0; joint < 0 && j < joint_count(*st); j++) line += " " + word(st->motion.joint[j]);
    s.reply(line);
    return R::ok;
}

// How each joint report describes a joint.
std::string pos_word(const EMC_JOINT_STAT &j) { return rsh_real(j.input); }
std::string velocity_word(const EMC_JOINT_STAT &j) { return rsh_real(j.velocity); }
std::string fault_word(const EMC_JOINT_STAT &j) { return j.fault ? "FAULT" : "OK"; }
std::string homed_word(const EMC_JOINT_STAT &j) { return j.homed ? "YES" : "NO"; }
std::string limit_word(const EMC_JOINT_STAT &j)
{
    return j.minHardLimit ? "MINHARD" : j.maxHardLimit ? "MAXHARD" : j.minSoftLimit ? "MINSOFT"
         : j.maxSoftLimit ? "MAXSOFT" : "OK";
}
std::string type_word(const EMC_JOINT_STAT &j)
{
    return j.jointType == EMC_LINEAR ? "LINEAR" : j.jointType == EMC_ANGULAR ? "ANGULAR" : "CUSTOM";
}
std::string units_word(const EMC_JOINT_STAT &j)
{
    return j.jointType == EMC_ANGULAR ? rsh_angular_units_name(j.units) : rsh_linear_units_name(j.units);
}

// The joint reports.
R get_joint_pos(RshServer &sv, RshSession &s, const RshArgs &a) { return joint_words(sv, s, a, "JOINT_POS", pos_word); }
R get_joint_velocity(RshServer &sv, RshSession &s, const RshArgs &a) { return joint_words(sv, s, a, "JOINT_VELOCITY", velocity_word); }
R get_joint_fault(RshServer &sv, RshSession &s, const RshArgs &a) { return joint_words(sv, s, a, "JOINT_FAULT", fault_word); }
R get_joint_homed(RshServer &sv, RshSession &s, const RshArgs &a) { return joint_words(sv, s, a, "JOINT_HOMED", homed_word); }
R get_joint_limit(RshServer &sv, RshSession &s, const RshArgs &a) { return joint_words(sv, s, a, "JOINT_LIMIT", limit_word); }
R get_joint_type(RshServer &sv, RshSession &s, const RshArgs &a) { return joint_words(sv, s, a, "JOINT_TYPE", type_word); }
R get_joint_units(RshServer &sv, RshSession &s, const RshArgs &a) { return joint_words(sv, s, a, "JOINT_UNITS", units_word); }

// set home [j|-1]
R set_home(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int joint;
    if (a.count() > 1) return R::nak;
    R r = joint_arg(s, a, 0, -1, false, &joint);
    if (r != R::ok) return r;
    EMC_JOINT_HOME m;
    m.joint = joint;
    return rsh_send(sv, s, m);
}

// set joint_unhome [j|-1|-2]
R set_unhome(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int joint;
    if (a.count() > 1) return R::nak;
    R r = joint_arg(s, a, 0, -1, true, &joint);
    if (r != R::ok) return r;
    EMC_JOINT_UNHOME m;
    m.joint = joint;
    return rsh_send(sv, s, m);
}

// The joint (joint mode) or axis (teleop) a jog names; false when it names none. *send is
// false when the machine cannot jog now: LinuxCNC acknowledged such jogs without sending.
bool jog_target(RshServer &sv, RshSession &s, const std::string &word, int *n, int *mode, bool *send)
{
    const EMC_STAT *st = rsh_status(sv, s);
    bool teleop = st && st->motion.traj.mode == EMC_TRAJ_MODE_TELEOP;
    long v;
    if (teleop) {
        *n = rsh_parse_axis(word);
        if (*n < 0) return false;
    } else {
        if (!rsh_parse_int(word, &v) || v < 0 || v >= EMCMOT_MAX_JOINTS) return false;
        *n = static_cast<int>(v);
    }
    *mode = teleop ? EMC_JOG_AXIS : EMC_JOG_JOINT;
    *send = st && st->task.state == EMC_TASK_STATE_ON &&
            (teleop || st->motion.traj.mode == EMC_TRAJ_MODE_FREE);
    return true;
}

// set jog <joint|axis> <speed>
R set_jog(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int n, mode;
    bool go;
    double speed;
    if (a.count() != 2 || !rsh_parse_real(a.at(1), &speed) || !jog_target(sv, s, a.at(0), &n, &mode, &go))
        return R::nak;
    if (!go) return R::ok;
    EMC_JOG_CONT m;
    m.joint_or_axis = n;
    m.jjogmode = mode;
    m.vel = speed / SECONDS_PER_MINUTE;
    return rsh_send(sv, s, m);
}

// set jog_incr <joint|axis> <speed> <increment>: the sign of speed is the direction.
R set_jog_incr(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int n, mode;
    bool go;
    double speed, incr;
    if (a.count() != 3 || !rsh_parse_real(a.at(1), &speed) || !rsh_parse_real(a.at(2), &incr) ||
        !jog_target(sv, s, a.at(0), &n, &mode, &go))
        return R::nak;
    if (!go) return R::ok;
    EMC_JOG_INCR m;
    m.joint_or_axis = n;
    m.jjogmode = mode;
    m.vel = speed / SECONDS_PER_MINUTE;
    m.incr = std::fabs(incr);
    return rsh_send(sv, s, m);
}

// set jog_stop <joint|axis>
R set_jog_stop(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int n, mode;
    bool go;
    if (a.count() != 1 || !jog_target(sv, s, a.at(0), &n, &mode, &go)) return R::nak;
    if (!go) return R::ok;
    EMC_JOG_STOP m;
    m.joint_or_axis = n;
    m.jjogmode = mode;
    return rsh_send(sv, s, m);
}

// Wait for the servo thread to run `periods` more times (at most HEARTBEAT_WAIT_S).
R heartbeat_wait(RshServer &sv, long periods)
{
    sv.client.poll();
    uint64_t start = sv.client.status().motion.heartbeat;
    double deadline = ui_now_s() + HEARTBEAT_WAIT_S;
    while (sv.client.status().motion.heartbeat - start < static_cast<uint64_t>(periods)) {
        if (ui_now_s() > deadline || sv.client.stop_requested()) return R::nak;
        if (sv.client.wait_status_change(0.05) == -ENOTCONN) return R::nak;
        sv.client.poll();
    }
    return R::ok;
}

// set wait_heartbeat [periods]
R set_wait_heartbeat(RshServer &sv, RshSession &, const RshArgs &a)
{
    long n = 1;
    if (a.count() > 1 || (a.count() == 1 && (!rsh_parse_int(a.at(0), &n) || n < 1))) return R::nak;
    return heartbeat_wait(sv, n);
}

// True when the joint(s) are homed; false while they still home; *bad when one neither
// homes nor is homed (the wait would never end).
bool homed_yet(const EMC_STAT &st, int joint, bool *bad)
{
    bool all = true;
    for (int j = 0; j < st.motion.traj.joints; j++) {
        if (joint >= 0 && j != joint) continue;
        const EMC_JOINT_STAT &js = st.motion.joint[j];
        if (!js.homed && !js.homing && joint >= 0) *bad = true;
        if (js.homing) all = false;
    }
    return all && (joint < 0 || st.motion.joint[joint].homed);
}

// set joint_wait_homed [j|-1] [timeout]
R set_joint_wait_homed(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int joint;
    double timeout = HOMED_WAIT_S;
    if (a.count() > 2 || (a.count() == 2 && !rsh_parse_real(a.at(1), &timeout))) return R::nak;
    R r = joint_arg(s, a, 0, -1, false, &joint);
    if (r != R::ok) return r;
    double deadline = ui_now_s() + timeout;
    for (;;) {
        sv.client.poll();
        bool bad = false;
        if (!sv.client.have_status()) return R::nak;
        if (homed_yet(sv.client.status(), joint, &bad)) return heartbeat_wait(sv, 1);
        if (bad || ui_now_s() > deadline || sv.client.stop_requested()) return R::nak;
        if (sv.client.wait_status_change(0.05) == -ENOTCONN) return R::nak;
    }
}

} // namespace

const RshSubcommand rsh_motion_subcommands[] = {
    {"abs_cmd_pos", get_abs_cmd_pos, nullptr, true},
    {"abs_act_pos", get_abs_act_pos, nullptr, true},
    {"rel_cmd_pos", get_rel_cmd_pos, nullptr, true},
    {"rel_act_pos", get_rel_act_pos, nullptr, true},
    {"pos_offset", get_pos_offset, nullptr, true},
    {"axis_velocity", get_axis_velocity, nullptr, true},
    {"joint_pos", get_joint_pos, nullptr, true},
    {"joint_velocity", get_joint_velocity, nullptr, true},
    {"joint_fault", get_joint_fault, nullptr, true},
    {"joint_homed", get_joint_homed, nullptr, true},
    {"joint_limit", get_joint_limit, nullptr, true},
    {"joint_type", get_joint_type, nullptr, true},
    {"joint_units", get_joint_units, nullptr, true},
    {"home", nullptr, set_home, true},
    {"joint_home", nullptr, set_home, true},
    {"joint_unhome", nullptr, set_unhome, true},
    {"jog", nullptr, set_jog, true},
    {"jog_incr", nullptr, set_jog_incr, true},
    {"jog_stop", nullptr, set_jog_stop, true},
    {"joint_wait_homed", nullptr, set_joint_wait_homed, true},
    {"wait_heartbeat", nullptr, set_wait_heartbeat, false},
    {nullptr, nullptr, nullptr, false},
};
