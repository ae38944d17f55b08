// rsh_session.cc: one request line of a session: echo, hello, get/set dispatch with the enable check, quit, shutdown, help.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

#include "rsh.hh"
#include "rsh_format.hh"

namespace {

// Failed HELLOs after which a connection is closed.
const int MAX_FAILED_HELLOS = 3;

const RshSubcommand *const tables[] = {rsh_session_subcommands, rsh_status_subcommands,
                                       rsh_motion_subcommands, rsh_program_subcommands};

// hello <password> <client> [<version>]
void hello(RshServer &sv, RshSession &s, const std::vector<std::string> &w)
{
    if (w.size() < 3 || w.size() > 4 || w[1] != sv.opt.connect_pw) {
        s.reply("HELLO NAK");
        if (++s.failed_hellos >= MAX_FAILED_HELLOS) {
            fprintf(stderr, "linuxcncrsh: %s: %d failed HELLOs, connection closed\n", s.peer.c_str(),
                    s.failed_hellos);
            s.closing = true;
        }
        return;
    }
    s.linked = true;
    s.client_name = w[2];
    s.prot_version = w.size() == 4 ? w[3] : RSH_SERVER_VERSION;
    double wanted = atof(s.prot_version.c_str());
    if (!sv.ini_version.empty() && atof(sv.ini_version.c_str()) < wanted)
        fprintf(stderr, "linuxcncrsh: client '%s' asks for protocol %s, the INI file is version %s\n",
                s.client_name.c_str(), s.prot_version.c_str(), sv.ini_version.c_str());
    if (!sv.opt.quiet)
        printf("linuxcncrsh: %s: client '%s' connected\n", s.peer.c_str(), s.client_name.c_str());
    s.reply("HELLO ACK " + sv.opt.name + " " + RSH_SERVER_VERSION);
}

// get <subcommand> [args]
void get(RshServer &sv, RshSession &s, const RshArgs &a)
{
    std::string name = a.args.empty() ? "" : rsh_upper(a.args[0]);
    const RshSubcommand *sub = a.args.empty() ? nullptr : rsh_find_subcommand(a.args[0]);
    if (!s.linked || !sub || !sub->get) {
        s.reply("GET " + name + (name.empty() ? "" : " ") + "NAK");
        return;
    }
    if (sub->get(sv, s, a) == RshResult::nak) s.reply("GET " + name + " NAK");
}

// set <subcommand> [args]; machine commands need the session to hold control.
void set(RshServer &sv, RshSession &s, const RshArgs &a)
{
    std::string name = a.args.empty() ? "" : rsh_upper(a.args[0]);
    const RshSubcommand *sub = a.args.empty() ? nullptr : rsh_find_subcommand(a.args[0]);
    if (!s.linked || !sub || !sub->set || (sub->control && sv.enabled_id != s.id)) {
        s.reply("SET " + name + (name.empty() ? "" : " ") + "NAK");
        return;
    }
    RshResult r = sub->set(sv, s, a);
    if (r == RshResult::nak) s.reply("SET " + name + " NAK");
    else if (r == RshResult::ok && s.verbose) s.reply("SET " + name + " ACK");
}

// shutdown: only from the session holding control; the server then exits.
void shutdown(RshServer &sv, RshSession &s)
{
    if (!s.linked || sv.enabled_id != s.id) {
        s.reply("SHUTDOWN NAK");
        return;
    }
    if (!sv.opt.quiet) printf("linuxcncrsh: shutdown requested by %s\n", s.peer.c_str());
    sv.shutdown = true;
}

} // namespace

// Find a subcommand in all tables (case-insensitive).
const RshSubcommand *rsh_find_subcommand(const std::string &name)
{
    std::string key = rsh_lower(name);
    for (const RshSubcommand *t : tables)
        for (; t->name; t++)
            if (key == t->name) return t;
    return nullptr;
}

// One request.
void rsh_handle_line(RshServer &sv, RshSession &s, const std::string &line)
{
    std::vector<std::string> w = rsh_words(line);
    if (w.empty()) return;
    std::string cmd = rsh_lower(w[0]);
    RshArgs a;
    a.args.assign(w.begin() + 1, w.end());
    a.line = line;
    if (cmd == "hello") hello(sv, s, w);
    else if (cmd == "get") get(sv, s, a);
    else if (cmd == "set") set(sv, s, a);
    else if (cmd == "quit") s.closing = true;
    else if (cmd == "shutdown") shutdown(sv, s);
    else if (cmd == "help") rsh_help(s, w.size() > 1 ? w[1] : "");
    else s.reply(rsh_upper(w[0]) + " NAK");
}

// Status for a get.
const EMC_STAT *rsh_status(RshServer &sv, RshSession &s)
{
    if (!s.update_auto && s.snapshot) return s.snapshot.get();
    sv.client.poll();
    return sv.client.have_status() ? &sv.client.status() : nullptr;
}

// Send a command and wait as the session asks.
RshResult rsh_send(RshServer &sv, RshSession &s, const NMLmsg &msg)
{
    int rc = sv.client.send(msg);
    if (rc < 0) {
        fprintf(stderr, "linuxcncrsh: %s not sent: %s\n", emc_symbol_lookup(msg.type), sv.client.error().c_str());
        return RshResult::nak;
    }
    s.last_serial = sv.client.last_serial();
    s.sent_any = true;
    if (s.wait_mode == UiWait::received) rc = sv.client.wait_received(s.last_serial, s.timeout_s);
    else if (s.wait_mode == UiWait::done) rc = sv.client.wait_done(s.last_serial, s.timeout_s);
    return rc == 0 ? RshResult::ok : RshResult::nak;
}

// One operator message into the texts 'get error/operator_text/operator_display' report.
void rsh_update_errors(RshServer &sv)
{
    NMLTYPE kind;
    std::string text;
    if (sv.client.read_message(&kind, &text) <= 0) return;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    for (char &c : text)
        if (c == '\n' || c == '\r') c = ' ';
    if (kind == EMC_OPERATOR_TEXT_TYPE || kind == NML_TEXT_TYPE) sv.operator_text = text;
    else if (kind == EMC_OPERATOR_DISPLAY_TYPE || kind == NML_DISPLAY_TYPE) sv.operator_display = text;
    else sv.error_text = text;
}

// A file on the search path.
std::string rsh_find_file(const RshServer &sv, const std::string &name)
{
    if (name.empty() || name[0] == '/') return name;
    for (const std::string &dir : sv.search_path) {
        std::string p = dir + "/" + name;
        if (access(p.c_str(), R_OK) == 0) return p;
    }
    return "";
}
