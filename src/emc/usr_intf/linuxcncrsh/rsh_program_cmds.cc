// rsh_program_cmds.cc: linuxcncrsh subcommands for programs and MDI (open, run, pause, resume, step, abort, mdi) and the unit reports.
#include "rsh.hh"
#include "rsh_format.hh"

namespace {

using R = RshResult;

// Reply "<name> <value>".
R say(RshSession &s, const std::string &name, const std::string &value)
{
    s.reply(name + " " + value);
    return R::ok;
}

// Send a message without fields.
template <class M>
R plain(RshServer &sv, RshSession &s, const RshArgs &a)
{
    if (a.count() != 0) return R::nak;
    M m;
    return rsh_send(sv, s, m);
}

// set mdi <text>: the rest of the line, as typed.
R set_mdi(RshServer &sv, RshSession &s, const RshArgs &a)
{
    std::string text = rsh_rest(a.line, 2);
    if (text.empty()) return R::nak;
    EMC_TASK_PLAN_EXECUTE m;
    if (!emc_set_text(m.command, text.c_str())) return R::nak;
    return rsh_send(sv, s, m);
}

// set open <file>: found on --path, else in the working directory (the INI's).
R set_open(RshServer &sv, RshSession &s, const RshArgs &a)
{
    std::string name = rsh_rest(a.line, 2);
    if (name.empty()) return R::nak;
    std::string file = rsh_find_file(sv, name);
    if (file.empty()) file = name;
    EMC_TASK_PLAN_OPEN m;
    if (!emc_set_text(m.file, file.c_str())) return R::nak;
    sv.last_opened = file;
    return rsh_send(sv, s, m);
}

// get open: the last file opened here.
R get_open(RshServer &sv, RshSession &s, const RshArgs &)
{
    return say(s, "OPEN", sv.last_opened.empty() ? "NONE" : sv.last_opened);
}

// set run [line]: from the start, from a line, or (-1) verify only.
R set_run(RshServer &sv, RshSession &s, const RshArgs &a)
{
    long line = 0;
    if (a.count() > 1 || (a.count() == 1 && !rsh_parse_int(a.at(0), &line))) return R::nak;
    EMC_TASK_PLAN_RUN m;
    m.line = static_cast<int32_t>(line);
    sv.program_start_line = static_cast<int>(line);
    return rsh_send(sv, s, m);
}

// set pause: needs wait mode RECEIVED, since a paused program is never done.
R set_pause(RshServer &sv, RshSession &s, const RshArgs &a)
{
    if (s.wait_mode == UiWait::done) return R::nak;
    return plain<EMC_TASK_PLAN_PAUSE>(sv, s, a);
}

// get program: the open program, or NONE.
R get_program(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    return say(s, "PROGRAM", st->task.file[0] ? st->task.file : "NONE");
}

// get program_line: the line executing.
R get_program_line(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    return say(s, "PROGRAM_LINE", std::to_string(rsh_program_line(st->task, sv.program_start_line)));
}

// get program_status: IDLE, RUNNING or PAUSED.
R get_program_status(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    if (!st) return R::nak;
    int interp = st->task.interpState;
    const char *what = interp == EMC_TASK_INTERP_IDLE ? "IDLE"
                     : (interp == EMC_TASK_INTERP_PAUSED || st->task.task_paused) ? "PAUSED" : "RUNNING";
    return say(s, "PROGRAM_STATUS", what);
}

// get program_codes: active G codes, F and S.
R get_program_codes(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? say(s, "PROGRAM_CODES", rsh_program_codes(st->task)) : R::nak;
}

// get program_units (program_linear_units): the interpreter's units.
R get_program_units(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? say(s, "PROGRAM_UNITS", rsh_program_units_name(st->task.programUnits)) : R::nak;
}

// The interpreter works in degrees.
R get_program_angular_units(RshServer &, RshSession &s, const RshArgs &)
{
    return say(s, "PROGRAM_ANGULAR_UNITS", "DEG");
}

// get user_linear_units: the machine's linear units.
R get_user_linear_units(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? say(s, "USER_LINEAR_UNITS", rsh_linear_units_name(st->motion.traj.linearUnits)) : R::nak;
}

// get user_angular_units: the machine's angular units.
R get_user_angular_units(RshServer &sv, RshSession &s, const RshArgs &)
{
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? say(s, "USER_ANGULAR_UNITS", rsh_angular_units_name(st->motion.traj.angularUnits)) : R::nak;
}

// Names of the display units.
const char *unit_name(RshUnits u)
{
    switch (u) {
    case RshUnits::inch: return "INCH";
    case RshUnits::mm: return "MM";
    case RshUnits::cm: return "CM";
    case RshUnits::deg: return "DEG";
    case RshUnits::rad: return "RAD";
    case RshUnits::grad: return "GRAD";
    default: return "AUTO";
    }
}

// get display_linear_units: the chosen units, or the program's with AUTO.
R get_display_linear_units(RshServer &sv, RshSession &s, const RshArgs &)
{
    if (s.linear_units != RshUnits::automatic) return say(s, "DISPLAY_LINEAR_UNITS", unit_name(s.linear_units));
    const EMC_STAT *st = rsh_status(sv, s);
    return st ? say(s, "DISPLAY_LINEAR_UNITS", rsh_program_units_name(st->task.programUnits)) : R::nak;
}

// get display_angular_units: the chosen units, or degrees with AUTO.
R get_display_angular_units(RshServer &, RshSession &s, const RshArgs &)
{
    return say(s, "DISPLAY_ANGULAR_UNITS", s.angular_units == RshUnits::automatic ? "DEG" : unit_name(s.angular_units));
}

// get linear_unit_conversion.
R get_linear_conversion(RshServer &, RshSession &s, const RshArgs &)
{
    return say(s, "LINEAR_UNIT_CONVERSION", unit_name(s.linear_units));
}

// get angular_unit_conversion.
R get_angular_conversion(RshServer &, RshSession &s, const RshArgs &)
{
    return say(s, "ANGULAR_UNIT_CONVERSION", unit_name(s.angular_units));
}

// set linear_unit_conversion inch|mm|cm|auto
R set_linear_conversion(RshServer &, RshSession &s, const RshArgs &a)
{
    std::string w = a.count() == 1 ? rsh_lower(a.at(0)) : "";
    if (w == "inch") s.linear_units = RshUnits::inch;
    else if (w == "mm") s.linear_units = RshUnits::mm;
    else if (w == "cm") s.linear_units = RshUnits::cm;
    else if (w == "auto") s.linear_units = RshUnits::automatic;
    else return R::nak;
    return R::ok;
}

// set angular_unit_conversion deg|rad|grad|auto
R set_angular_conversion(RshServer &, RshSession &s, const RshArgs &a)
{
    std::string w = a.count() == 1 ? rsh_lower(a.at(0)) : "";
    if (w == "deg") s.angular_units = RshUnits::deg;
    else if (w == "rad") s.angular_units = RshUnits::rad;
    else if (w == "grad") s.angular_units = RshUnits::grad;
    else if (w == "auto") s.angular_units = RshUnits::automatic;
    else return R::nak;
    return R::ok;
}

} // namespace

const RshSubcommand rsh_program_subcommands[] = {
    {"mdi", nullptr, set_mdi, true},
    {"task_plan_init", nullptr, plain<EMC_TASK_PLAN_INIT>, true},
    {"open", get_open, set_open, true},
    {"run", nullptr, set_run, true},
    {"pause", nullptr, set_pause, true},
    {"resume", nullptr, plain<EMC_TASK_PLAN_RESUME>, true},
    {"step", nullptr, plain<EMC_TASK_PLAN_STEP>, true},
    {"abort", nullptr, plain<EMC_TASK_ABORT>, true},
    {"program", get_program, nullptr, true},
    {"program_line", get_program_line, nullptr, true},
    {"program_status", get_program_status, nullptr, true},
    {"program_codes", get_program_codes, nullptr, true},
    {"program_units", get_program_units, nullptr, true},
    {"program_linear_units", get_program_units, nullptr, true},
    {"program_angular_units", get_program_angular_units, nullptr, true},
    {"user_linear_units", get_user_linear_units, nullptr, true},
    {"user_angular_units", get_user_angular_units, nullptr, true},
    {"display_linear_units", get_display_linear_units, nullptr, true},
    {"display_angular_units", get_display_angular_units, nullptr, true},
    {"linear_unit_conversion", get_linear_conversion, set_linear_conversion, false},
    {"angular_unit_conversion", get_angular_conversion, set_angular_conversion, false},
    {nullptr, nullptr, nullptr, false},
};
