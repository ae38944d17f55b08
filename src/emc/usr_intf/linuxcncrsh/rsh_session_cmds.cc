// rsh_session_cmds.cc: linuxcncrsh subcommands about the session and the server: echo, verbose, enable, waits, timeouts, updates, messages, units, INI.
#include <sys/time.h>

#include <cstdio>
#include <cstdlib>

#include "inifile.hh"
#include "rsh.hh"
#include "rsh_format.hh"

namespace {

using R = RshResult;

// An on/off session flag: get prints "<NAME> ON|OFF", set takes on/off.
R flag_get(RshSession &s, const char *name, bool value)
{
    s.reply(std::string(name) + (value ? " ON" : " OFF"));
    return R::ok;
}

// Set a session flag from an on/off argument.
R flag_set(const RshArgs &a, bool *flag)
{
    int v = a.count() == 1 ? rsh_parse_on_off(a.at(0)) : -1;
    if (v < 0) return R::nak;
    *flag = v != 0;
    return R::ok;
}

// echo, verbose and enable.
R get_echo(RshServer &, RshSession &s, const RshArgs &) { return flag_get(s, "ECHO", s.echo); }
R set_echo(RshServer &, RshSession &s, const RshArgs &a) { return flag_set(a, &s.echo); }
R get_verbose(RshServer &, RshSession &s, const RshArgs &) { return flag_get(s, "VERBOSE", s.verbose); }
R set_verbose(RshServer &, RshSession &s, const RshArgs &a) { return flag_set(a, &s.verbose); }
R get_enable(RshServer &sv, RshSession &s, const RshArgs &) { return flag_get(s, "ENABLE", sv.enabled_id == s.id); }

// set enable <password>|off: control passes to this session (one session at a time).
R set_enable(RshServer &sv, RshSession &s, const RshArgs &a)
{
    if (a.count() != 1) return R::nak;
    if (rsh_lower(a.at(0)) == "off") {
        if (sv.enabled_id == s.id) sv.enabled_id = 0;
        return R::ok;
    }
    if (a.at(0) != sv.opt.enable_pw) return R::nak;
    sv.enabled_id = s.id;
    if (!sv.opt.quiet) printf("linuxcncrsh: %s now holds control\n", s.peer.c_str());
    return R::ok;
}

// get comm_mode: ASCII.
R get_comm_mode(RshServer &, RshSession &s, const RshArgs &)
{
    s.reply("COMM_MODE ASCII");
    return R::ok;
}

// Only the text protocol exists (LinuxCNC never implemented the binary one either).
R set_comm_mode(RshServer &, RshSession &, const RshArgs &a)
{
    return a.count() == 1 && rsh_lower(a.at(0)) == "ascii" ? R::ok : R::nak;
}

// get comm_prot: the session's protocol version.
R get_comm_prot(RshServer &, RshSession &s, const RshArgs &)
{
    s.reply("COMM_PROT " + s.prot_version);
    return R::ok;
}

// set comm_prot <version>: any version up to the server's.
R set_comm_prot(RshServer &, RshSession &s, const RshArgs &a)
{
    double v;
    if (a.count() != 1 || !rsh_parse_real(a.at(0), &v) || v <= 0 || v > atof(RSH_SERVER_VERSION)) return R::nak;
    s.prot_version = a.at(0);
    return R::ok;
}

// get inifile: the configuration's INI file.
R get_inifile(RshServer &sv, RshSession &s, const RshArgs &)
{
    s.reply("INIFILE " + sv.ini_path);
    return R::ok;
}

// get plat: the platform.
R get_plat(RshServer &, RshSession &s, const RshArgs &)
{
    s.reply("PLAT Linux");
    return R::ok;
}

// get ini <var> <section>
R get_ini(RshServer &sv, RshSession &s, const RshArgs &a)
{
    if (a.count() != 2) return R::nak;
    IniFile ini;
    ini.SetQuiet(true);
    if (!ini.Open(sv.ini_path)) return R::nak;
    std::optional<std::string> v = ini.Find(a.at(0), a.at(1));
    if (!v) return R::nak;
    s.reply("INI " + *v);
    return R::ok;
}

// get debug: the debug flags.
R get_debug(RshServer &sv, RshSession &s, const RshArgs &)
{
    s.reply("DEBUG " + std::to_string(sv.debug));
    return R::ok;
}

// set debug <value>: task's debug flags, and ours.
R set_debug(RshServer &sv, RshSession &s, const RshArgs &a)
{
    long v;
    if (a.count() != 1 || !rsh_parse_int(a.at(0), &v)) return R::nak;
    EMC_SET_DEBUG m;
    m.debug = static_cast<int32_t>(v);
    sv.debug = v;
    return rsh_send(sv, s, m);
}

// received|done as a wait mode.
bool parse_wait(const std::string &w, UiWait *mode)
{
    std::string l = rsh_lower(w);
    if (l == "received") *mode = UiWait::received;
    else if (l == "done") *mode = UiWait::done;
    else return false;
    return true;
}

// get wait_mode (set_wait): RECEIVED or DONE.
R get_wait_mode(RshServer &, RshSession &s, const RshArgs &)
{
    s.reply(s.wait_mode == UiWait::done ? "WAIT_MODE DONE" : "WAIT_MODE RECEIVED");
    return R::ok;
}

// set wait_mode received|done.
R set_wait_mode(RshServer &, RshSession &s, const RshArgs &a)
{
    return a.count() == 1 && parse_wait(a.at(0), &s.wait_mode) ? R::ok : R::nak;
}

// The old name of wait_mode still works, with a warning line (as LinuxCNC 2.10 gives).
R set_set_wait(RshServer &sv, RshSession &s, const RshArgs &a)
{
    s.reply("WARNING: \"set_wait\" is deprecated and will go away; use \"wait_mode\"");
    return set_wait_mode(sv, s, a);
}

// set wait received|done: wait for this session's last command.
R set_wait(RshServer &sv, RshSession &s, const RshArgs &a)
{
    UiWait mode;
    if (a.count() != 1 || !parse_wait(a.at(0), &mode) || !s.sent_any) return R::nak;
    int rc = mode == UiWait::done ? sv.client.wait_done(s.last_serial, s.timeout_s)
                                  : sv.client.wait_received(s.last_serial, s.timeout_s);
    return rc == 0 ? R::ok : R::nak;
}

// get timeout: seconds a wait may take (0: no limit).
R get_timeout(RshServer &, RshSession &s, const RshArgs &)
{
    s.reply("TIMEOUT " + rsh_real(s.timeout_s));
    return R::ok;
}

// set timeout <seconds>: <= 0 waits without a limit.
R set_timeout(RshServer &, RshSession &s, const RshArgs &a)
{
    double t;
    if (a.count() != 1 || !rsh_parse_real(a.at(0), &t)) return R::nak;
    s.timeout_s = t > 0 ? t : 0;
    return R::ok;
}

// get update: AUTO or NONE.
R get_update(RshServer &, RshSession &s, const RshArgs &)
{
    s.reply(s.update_auto ? "UPDATE AUTO" : "UPDATE NONE");
    return R::ok;
}

// set update none|auto: none freezes what gets show until 'set update_status'.
R set_update(RshServer &sv, RshSession &s, const RshArgs &a)
{
    std::string v = a.count() == 1 ? rsh_lower(a.at(0)) : "";
    if (v != "none" && v != "auto") return R::nak;
    s.update_auto = v == "auto";
    if (!s.update_auto && !s.snapshot) {
        sv.client.poll();
        s.snapshot.reset(new EMC_STAT(sv.client.status()));
    }
    return R::ok;
}

// set update_status: take a new status snapshot for update none.
R set_update_status(RshServer &sv, RshSession &s, const RshArgs &a)
{
    if (a.count() != 0) return R::nak;
    sv.client.poll();
    s.snapshot.reset(new EMC_STAT(sv.client.status()));
    return R::ok;
}

// A message text: read one message from emcError, report and forget the text.
R message(RshServer &sv, RshSession &s, const char *name, std::string &text)
{
    rsh_update_errors(sv);
    s.reply(std::string(name) + " " + (text.empty() ? "OK" : text));
    text.clear();
    return R::ok;
}

// The three message texts.
R get_error(RshServer &sv, RshSession &s, const RshArgs &) { return message(sv, s, "ERROR", sv.error_text); }
R get_operator_text(RshServer &sv, RshSession &s, const RshArgs &) { return message(sv, s, "OPERATOR_TEXT", sv.operator_text); }
R get_operator_display(RshServer &sv, RshSession &s, const RshArgs &) { return message(sv, s, "OPERATOR_DISPLAY", sv.operator_display); }

// get time: seconds since 1970.
R get_time(RshServer &, RshSession &s, const RshArgs &)
{
    struct timeval tv;
    gettimeofday(&tv, nullptr);
    s.reply("TIME " + rsh_real(tv.tv_sec + tv.tv_usec * 1e-6));
    return R::ok;
}

} // namespace

const RshSubcommand rsh_session_subcommands[] = {
    {"echo", get_echo, set_echo, false},
    {"verbose", get_verbose, set_verbose, false},
    {"enable", get_enable, set_enable, false},
    {"comm_mode", get_comm_mode, set_comm_mode, false},
    {"comm_prot", get_comm_prot, set_comm_prot, false},
    {"inifile", get_inifile, nullptr, false},
    {"plat", get_plat, nullptr, false},
    {"ini", get_ini, nullptr, false},
    {"debug", get_debug, set_debug, true},
    {"wait_mode", get_wait_mode, set_wait_mode, false},
    {"set_wait", get_wait_mode, set_set_wait, false},
    {"wait", nullptr, set_wait, false},
    {"timeout", get_timeout, set_timeout, false},
    {"set_timeout", get_timeout, set_timeout, false},
    {"update", get_update, set_update, false},
    {"update_status", nullptr, set_update_status, false},
    {"error", get_error, nullptr, false},
    {"operator_text", get_operator_text, nullptr, false},
    {"operator_display", get_operator_display, nullptr, false},
    {"time", get_time, nullptr, false},
    {nullptr, nullptr, nullptr, false},
};
