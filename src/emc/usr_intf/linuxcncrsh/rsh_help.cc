// rsh_help.cc: linuxcncrsh's 'help' replies: the commands, and the subcommands get and set know (from the handler tables).
#include <cstring>

#include "rsh.hh"
#include "rsh_format.hh"

namespace {

// Usage lines of the top-level commands.
struct Usage {
    const char *command;
    const char *text;
};

const Usage usages[] = {
    {"hello", "hello <password> <client name> [<protocol version>]: start the session (needed before get/set)"},
    {"get", "get <subcommand> [<arguments>]: report a value; 'help get' lists the subcommands"},
    {"set", "set <subcommand> <arguments>: change a setting or command the machine; 'help set' lists them"},
    {"quit", "quit: close this connection (the machine keeps its state)"},
    {"shutdown", "shutdown: stop linuxcncrsh (and LinuxCNC when it is the display); needs 'set enable'"},
    {"help", "help [<command>]: this text"},
};

const RshSubcommand *const tables[] = {rsh_session_subcommands, rsh_status_subcommands,
                                       rsh_motion_subcommands, rsh_program_subcommands};

// The subcommands that have a get (or set) handler, a few per line.
void list_subcommands(RshSession &s, bool want_set)
{
    std::string line;
    for (const RshSubcommand *t : tables)
        for (; t->name; t++) {
            if (!(want_set ? t->set : t->get)) continue;
            if (line.size() + strlen(t->name) > 70) {
                s.reply(line);
                line.clear();
            }
            line += line.empty() ? "  " : " ";
            line += t->name;
        }
    if (!line.empty()) s.reply(line);
}

} // namespace

// help [command]
void rsh_help(RshSession &s, const std::string &topic)
{
    std::string t = rsh_lower(topic);
    if (t == "get" || t == "set") {
        s.reply(usages[t == "get" ? 1 : 2].text);
        s.reply(t == "get" ? "Subcommands of get:" : "Subcommands of set (most need 'set enable <password>'):");
        list_subcommands(s, t == "set");
        return;
    }
    for (const Usage &u : usages)
        if (t == u.command) {
            s.reply(u.text);
            return;
        }
    if (!t.empty()) s.reply("help: no command '" + topic + "'");
    s.reply("Commands (not case sensitive; replies end in \\r\\n):");
    for (const Usage &u : usages) s.reply(std::string("  ") + u.text);
}
