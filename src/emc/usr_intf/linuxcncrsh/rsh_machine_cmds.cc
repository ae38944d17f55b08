// rsh_machine_cmds.cc: linuxcncrsh subcommands for the machine: E-stop, power, mode, coolant, spindles, brake, overrides, tool, probe, limits.
#include <cmath>

#include "rsh.hh"
#include "rsh_format.hh"

namespace {

using R = RshResult;

// Spindle speed without an S word (LinuxCNC's), unless [DISPLAY]DEFAULT_SPINDLE_SPEED is set.
const double FALLBACK_SPINDLE_RPM = 500.0;

// Reply "<NAME> ON|OFF".
R on_off_reply(RshSession &s, const char *name, bool on)
{
    s.reply(std::string(name) + (on ? " ON" : " OFF"));
    return R::ok;
}

// The single on/off argument of a set, or -1.
int on_off_arg(const RshArgs &a)
{
    return a.count() >= 1 ? rsh_parse_on_off(a.at(0)) : -1;
}

// Send a message of type M built by fill().
template <class M, class Fill>
R send(RshServer &sv, RshSession &s, Fill fill)
{
    M m;
    fill(m);
    return rsh_send(sv, s, m);
}

// The spindles named by argument i (default dflt: -1 all or a number).
R spindles(RshSession &s, const EMC_STAT &st, const RshArgs &a, size_t i, int dflt, int *lo, int *hi)
{
    int n = st.motion.traj.spindles > 0 ? st.motion.traj.spindles : 1;
    long v = dflt;
    if (a.count() > i && (!rsh_parse_int(a.at(i), &v) || v < -1 || v >= n)) {
        s.reply("error: invalid spindle: " + a.at(i) + " (valid: -1 - " + std::to_string(n - 1) + ")");
        return R::replied;
    }
    *lo = v < 0 ? 0 : static_cast<int>(v);
    *hi = v < 0 ? n - 1 : static_cast<int>(v);
    return R::ok;
}

// get estop: ON while in E-stop.
R get_estop(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? on_off_reply(s, "ESTOP", st->task.state == EMC_TASK_STATE_ESTOP) : R::nak;
}

// set estop on|off: E-stop, or E-stop reset.
R set_estop(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int on = on_off_arg(a);
    if (on < 0) return R::nak;
    return send<EMC_TASK_SET_STATE>(sv, s, [&](EMC_TASK_SET_STATE &m) {
        m.state = on ? EMC_TASK_STATE_ESTOP : EMC_TASK_STATE_ESTOP_RESET;
    });
}

// get machine: ON while the machine is on.
R get_machine(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? on_off_reply(s, "MACHINE", st->task.state == EMC_TASK_STATE_ON) : R::nak;
}

// set machine on|off.
R set_machine(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int on = on_off_arg(a);
    if (on < 0) return R::nak;
    return send<EMC_TASK_SET_STATE>(sv, s, [&](EMC_TASK_SET_STATE &m) {
        m.state = on ? EMC_TASK_STATE_ON : EMC_TASK_STATE_OFF;
    });
}

// get mode: MANUAL, AUTO or MDI.
R get_mode(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    int m = st->task.mode;
    s.reply(m == EMC_TASK_MODE_AUTO ? "MODE AUTO" : m == EMC_TASK_MODE_MDI ? "MODE MDI" : "MODE MANUAL");
    return R::ok;
}

// set mode manual|auto|mdi.
R set_mode(RshServer &sv, RshSession &s, const RshArgs &a)
{
    std::string w = a.count() == 1 ? rsh_lower(a.at(0)) : "";
    int mode = w == "manual" ? EMC_TASK_MODE_MANUAL : w == "auto" ? EMC_TASK_MODE_AUTO
             : w == "mdi" ? EMC_TASK_MODE_MDI : 0;
    if (!mode) return R::nak;
    return send<EMC_TASK_SET_MODE>(sv, s, [&](EMC_TASK_SET_MODE &m) { m.mode = mode; });
}

// get mist / set mist on|off.
R get_mist(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? on_off_reply(s, "MIST", st->io.coolant.mist != 0) : R::nak;
}

R set_mist(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int on = on_off_arg(a);
    if (on < 0) return R::nak;
    if (on) return send<EMC_COOLANT_MIST_ON>(sv, s, [](EMC_COOLANT_MIST_ON &) {});
    return send<EMC_COOLANT_MIST_OFF>(sv, s, [](EMC_COOLANT_MIST_OFF &) {});
}

// get flood / set flood on|off.
R get_flood(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? on_off_reply(s, "FLOOD", st->io.coolant.flood != 0) : R::nak;
}

R set_flood(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int on = on_off_arg(a);
    if (on < 0) return R::nak;
    if (on) return send<EMC_COOLANT_FLOOD_ON>(sv, s, [](EMC_COOLANT_FLOOD_ON &) {});
    return send<EMC_COOLANT_FLOOD_OFF>(sv, s, [](EMC_COOLANT_FLOOD_OFF &) {});
}

// get spindle [n|-1]: "SPINDLE n FORWARD|REVERSE|INCREASE|DECREASE|OFF" for spindle n
// (default 0), or a line per spindle for -1.
R get_spindle(RshServer &sv, RshSession &s, const RshArgs &a)
{
    const EMC_STAT *st = rsh_status(sv, s);
    int lo, hi;
    if (!st) return R::nak;
    R r = spindles(s, *st, a, 0, 0, &lo, &hi);
    if (r != R::ok) return r;
    for (int n = lo; n <= hi; n++) {
        const EMC_SPINDLE_STAT &sp = st->motion.spindle[n];
        const char *what = sp.increasing > 0 ? "INCREASE" : sp.increasing < 0 ? "DECREASE"
                         : sp.direction > 0 ? "FORWARD" : sp.direction < 0 ? "REVERSE" : "OFF";
        s.reply("SPINDLE " + std::to_string(n) + " " + what);
    }
    return R::ok;
}

// One spindle command of set spindle.
R spindle_command(RshServer &sv, RshSession &s, const EMC_STAT &st, const std::string &what, int n)
{
    double sword = std::fabs(st.task.activeSettings[2]);
    double dflt = sv.default_spindle_speed > 0 ? sv.default_spindle_speed : FALLBACK_SPINDLE_RPM;
    double rpm = sword > 0 ? sword : dflt;
    double speed = st.motion.spindle[n].speed;
    if (what == "forward" || what == "reverse")
        return send<EMC_SPINDLE_ON>(sv, s, [&](EMC_SPINDLE_ON &m) {
            m.spindle = n;
            m.speed = what == "forward" ? rpm : -rpm;
        });
    if (what == "increase")
        return send<EMC_SPINDLE_INCREASE>(sv, s, [&](EMC_SPINDLE_INCREASE &m) { m.spindle = n; m.speed = speed; });
    if (what == "decrease")
        return send<EMC_SPINDLE_DECREASE>(sv, s, [&](EMC_SPINDLE_DECREASE &m) { m.spindle = n; m.speed = speed; });
    if (what == "constant")
        return send<EMC_SPINDLE_CONSTANT>(sv, s, [&](EMC_SPINDLE_CONSTANT &m) { m.spindle = n; m.speed = speed; });
    if (what == "off") return send<EMC_SPINDLE_OFF>(sv, s, [&](EMC_SPINDLE_OFF &m) { m.spindle = n; });
    return R::nak;
}

// set spindle forward|reverse|increase|decrease|constant|off [n|-1]
R set_spindle(RshServer &sv, RshSession &s, const RshArgs &a)
{
    const EMC_STAT *st = rsh_status(sv, s);
    int lo, hi;
    if (!st || a.count() < 1 || a.count() > 2) return R::nak;
    R r = spindles(s, *st, a, 1, 0, &lo, &hi);
    if (r != R::ok) return r;
    EMC_STAT now = *st;
    for (int n = lo; n <= hi && r == R::ok; n++) r = spindle_command(sv, s, now, rsh_lower(a.at(0)), n);
    return r;
}

// get brake [n|-1]: "BRAKE ON|OFF" per spindle.
R get_brake(RshServer &sv, RshSession &s, const RshArgs &a)
{
    const EMC_STAT *st = rsh_status(sv, s);
    int lo, hi;
    if (!st) return R::nak;
    R r = spindles(s, *st, a, 0, 0, &lo, &hi);
    if (r != R::ok) return r;
    for (int n = lo; n <= hi; n++) on_off_reply(s, "BRAKE", st->motion.spindle[n].brake != 0);
    return R::ok;
}

// set brake on|off [n|-1]
R set_brake(RshServer &sv, RshSession &s, const RshArgs &a)
{
    const EMC_STAT *st = rsh_status(sv, s);
    int lo, hi, on = on_off_arg(a);
    if (!st || on < 0 || a.count() > 2) return R::nak;
    R r = spindles(s, *st, a, 1, 0, &lo, &hi);
    for (int n = lo; n <= hi && r == R::ok; n++) {
        if (on) r = send<EMC_SPINDLE_BRAKE_ENGAGE>(sv, s, [&](EMC_SPINDLE_BRAKE_ENGAGE &m) { m.spindle = n; });
        else r = send<EMC_SPINDLE_BRAKE_RELEASE>(sv, s, [&](EMC_SPINDLE_BRAKE_RELEASE &m) { m.spindle = n; });
    }
    return r;
}

// An override as a whole percentage.
R percent_reply(RshSession &s, const char *name, double scale)
{
    s.reply(std::string(name) + " " + std::to_string(static_cast<long>(std::floor(scale * 100.0 + 0.5))));
    return R::ok;
}

// get feed_override: whole percent.
R get_feed_override(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? percent_reply(s, "FEED_OVERRIDE", st->motion.traj.scale) : R::nak;
}

// set feed_override <percent>.
R set_feed_override(RshServer &sv, RshSession &s, const RshArgs &a)
{
    double pct;
    if (a.count() != 1 || !rsh_parse_real(a.at(0), &pct) || pct < 0) return R::nak;
    return send<EMC_TRAJ_SET_SCALE>(sv, s, [&](EMC_TRAJ_SET_SCALE &m) { m.scale = pct / 100.0; });
}

// get spindle_override [n|-1]: "SPINDLE_OVERRIDE n percent" per spindle.
R get_spindle_override(RshServer &sv, RshSession &s, const RshArgs &a)
{
    const EMC_STAT *st = rsh_status(sv, s);
    int lo, hi;
    if (!st) return R::nak;
    R r = spindles(s, *st, a, 0, 0, &lo, &hi);
    if (r != R::ok) return r;
    for (int n = lo; n <= hi; n++)
        s.reply("SPINDLE_OVERRIDE " + std::to_string(n) + " " + rsh_real(st->motion.spindle[n].spindle_scale * 100.0));
    return R::ok;
}

// set spindle_override <percent> [n|-1]
R set_spindle_override(RshServer &sv, RshSession &s, const RshArgs &a)
{
    const EMC_STAT *st = rsh_status(sv, s);
    double pct;
    int lo, hi;
    if (!st || a.count() < 1 || a.count() > 2 || !rsh_parse_real(a.at(0), &pct) || pct < 0) return R::nak;
    R r = spindles(s, *st, a, 1, 0, &lo, &hi);
    for (int n = lo; n <= hi && r == R::ok; n++)
        r = send<EMC_TRAJ_SET_SPINDLE_SCALE>(sv, s, [&](EMC_TRAJ_SET_SPINDLE_SCALE &m) {
            m.spindle = n;
            m.scale = pct / 100.0;
        });
    return r;
}

// get tool: the tool in the spindle.
R get_tool(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    s.reply("TOOL " + std::to_string(st->io.tool.toolInSpindle));
    return R::ok;
}

// get tool_offset: the length offset in force (Z).
R get_tool_offset(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    s.reply("TOOL_OFFSET " + rsh_real(st->task.toolOffset.tran.z));
    return R::ok;
}

// set tool_offset <tool> <length> <diameter>: the tool's row of the tool table.
R set_tool_offset(RshServer &sv, RshSession &s, const RshArgs &a)
{
    long tool;
    double length, diameter;
    if (a.count() != 3 || !rsh_parse_int(a.at(0), &tool) || tool < 0 || !rsh_parse_real(a.at(1), &length) ||
        !rsh_parse_real(a.at(2), &diameter))
        return R::nak;
    int row = -1;
    char err[256];
    if (tooldata_t *td = tooldata_open(0, err, sizeof err)) {
        tooldata_entry_t e;
        row = tooldata_find(td, static_cast<int>(tool), &e);
        tooldata_close(td);
    }
    return send<EMC_TOOL_SET_OFFSET>(sv, s, [&](EMC_TOOL_SET_OFFSET &m) {
        m.pocket = row < 0 ? -1 : row;
        m.toolno = static_cast<int32_t>(tool);
        m.offset.tran.z = length;
        m.diameter = diameter;
    });
}

// set load_tool_table <file>
R set_load_tool_table(RshServer &sv, RshSession &s, const RshArgs &a)
{
    std::string name = rsh_rest(a.line, 2);
    if (name.empty()) return R::nak;
    std::string file = rsh_find_file(sv, name);
    EMC_TOOL_LOAD_TOOL_TABLE m;
    if (!emc_set_text(m.file, (file.empty() ? name : file).c_str())) return R::nak;
    return rsh_send(sv, s, m);
}

// get probe_tripped: the probe tripped since the last clear.
R get_probe_tripped(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    s.reply("PROBE_TRIPPED " + std::to_string(st->motion.traj.probe_tripped));
    return R::ok;
}

// get probe_value: the probe input now.
R get_probe_value(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    s.reply("PROBE_VALUE " + std::to_string(st->motion.traj.probeval));
    return R::ok;
}

// set probe_clear: forget that the probe tripped.
R set_probe_clear(RshServer &sv, RshSession &s, const RshArgs &)
{
    return send<EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG>(sv, s, [](EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG &) {});
}

// set probe <x> <y> <z>: a G38.2 move as MDI (MDI mode only).
R set_probe(RshServer &sv, RshSession &s, const RshArgs &a)
{
    const EMC_STAT *st = rsh_status(sv, s);
    double x, y, z;
    if (!st || st->task.mode != EMC_TASK_MODE_MDI || a.count() != 3 || !rsh_parse_real(a.at(0), &x) ||
        !rsh_parse_real(a.at(1), &y) || !rsh_parse_real(a.at(2), &z))
        return R::nak;
    EMC_TASK_PLAN_EXECUTE m;
    emc_set_text(m.command, ("G38.2 X" + rsh_real(x) + " Y" + rsh_real(y) + " Z" + rsh_real(z)).c_str());
    return rsh_send(sv, s, m);
}

// get teleop_enable: ON while axes jog (teleop mode).
R get_teleop_enable(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? on_off_reply(s, "TELEOP_ENABLE", st->motion.traj.mode == EMC_TRAJ_MODE_TELEOP) : R::nak;
}

// set teleop_enable on|off: only in manual mode (world or joint jogging).
R set_teleop_enable(RshServer &sv, RshSession &s, const RshArgs &a)
{
    const EMC_STAT *st = rsh_status(sv, s);
    int on = on_off_arg(a);
    if (!st || on < 0 || st->task.mode != EMC_TASK_MODE_MANUAL) return R::nak;
    return send<EMC_TRAJ_SET_TELEOP_ENABLE>(sv, s, [&](EMC_TRAJ_SET_TELEOP_ENABLE &m) { m.enable = on; });
}

// get kinematics_type: 1 identity, 2 serial, 3 parallel, 4 custom.
R get_kinematics_type(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    s.reply("KINEMATICS_TYPE " + std::to_string(st->motion.traj.kinematics_type));
    return R::ok;
}

// get override_limits: whether joint 0's limits are overridden.
R get_override_limits(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    s.reply("OVERRIDE_LIMITS " + std::to_string(st->motion.joint[0].overrideLimits));
    return R::ok;
}

// set override_limits on|off: on lets joints jog off their hardware limits.
R set_override_limits(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int on = on_off_arg(a);
    if (on < 0) return R::nak;
    return send<EMC_JOINT_OVERRIDE_LIMITS>(sv, s, [&](EMC_JOINT_OVERRIDE_LIMITS &m) { m.joint = on ? 0 : -1; });
}

// get optional_stop / set optional_stop on|off (M1).
R get_optional_stop(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    s.reply("OPTIONAL_STOP " + std::to_string(st->task.optional_stop_state));
    return R::ok;
}

R set_optional_stop(RshServer &sv, RshSession &s, const RshArgs &a)
{
    int on = on_off_arg(a);
    if (on < 0) return R::nak;
    return send<EMC_TASK_PLAN_SET_OPTIONAL_STOP>(sv, s, [&](EMC_TASK_PLAN_SET_OPTIONAL_STOP &m) {
        m.state = static_cast<uint8_t>(on);
    });
}

} // namespace

const RshSubcommand rsh_status_subcommands[] = {
    {"estop", get_estop, set_estop, true},
    {"machine", get_machine, set_machine, true},
    {"mode", get_mode, set_mode, true},
    {"mist", get_mist, set_mist, true},
    {"flood", get_flood, set_flood, true},
    {"spindle", get_spindle, set_spindle, true},
    {"brake", get_brake, set_brake, true},
    {"feed_override", get_feed_override, set_feed_override, true},
    {"spindle_override", get_spindle_override, set_spindle_override, true},
    {"tool", get_tool, nullptr, true},
    {"tool_offset", get_tool_offset, set_tool_offset, true},
    {"load_tool_table", nullptr, set_load_tool_table, true},
    {"probe_tripped", get_probe_tripped, nullptr, true},
    {"probe_value", get_probe_value, nullptr, true},
    {"probe_clear", nullptr, set_probe_clear, true},
    {"probe", nullptr, set_probe, true},
    {"teleop_enable", get_teleop_enable, set_teleop_enable, true},
    {"kinematics_type", get_kinematics_type, nullptr, true},
    {"override_limits", get_override_limits, set_override_limits, true},
    {"optional_stop", get_optional_stop, set_optional_stop, true},
    {nullptr, nullptr, nullptr, false},
};
