// rsh.hh: linuxcncrsh's server, sessions and the get/set handler tables.
#ifndef RSH_HH
#define RSH_HH

#include <csignal>
#include <memory>
#include <string>
#include <vector>

#include "ui_client.hh"

// LinuxCNC's defaults, kept so existing scripts work.
#define RSH_DEFAULT_PORT 5007
#define RSH_DEFAULT_NAME "EMCNETSVR"
#define RSH_DEFAULT_CONNECT_PW "EMC"
#define RSH_DEFAULT_ENABLE_PW "EMCTOO"
// Protocol version this server speaks (HELLO ACK <name> <version>).
#define RSH_SERVER_VERSION "1.1"

// Command-line settings.
struct RshOptions {
    int port = RSH_DEFAULT_PORT;
    std::string name = RSH_DEFAULT_NAME;
    std::string connect_pw = RSH_DEFAULT_CONNECT_PW;
    std::string enable_pw = RSH_DEFAULT_ENABLE_PW;
    int max_sessions = 0;                 // 0 or less: no limit
    std::vector<std::string> path;        // where relative file names are looked up
    std::vector<std::string> bind;        // addresses to listen on (default: loopback)
    bool quiet = false;
    std::string ini;
};

// Parse argv; returns 0 to run, 1 after a usage error (message printed), 2 after --help.
int rsh_parse_options(int argc, char **argv, RshOptions &opt);

// Unit shown by the display_*_units replies: AUTO follows the program.
enum class RshUnits { automatic, inch, mm, cm, deg, rad, grad };

// One client connection.
struct RshSession {
    int fd = -1;
    int id = 0;
    std::string peer;          // "address:port"
    std::string in, out;       // bytes received but not yet a line / not yet sent
    bool closing = false;      // close once out is sent
    bool linked = false;       // a HELLO succeeded
    int failed_hellos = 0;
    std::string client_name;
    std::string prot_version = RSH_SERVER_VERSION;
    bool echo = true;          // reported by 'get echo'; requests are never sent back (as 2.10)
    bool verbose = false;
    UiWait wait_mode = UiWait::received;
    double timeout_s = 0;      // 0: wait without a limit
    bool update_auto = true;   // false: gets show the snapshot of 'set update_status'
    std::unique_ptr<EMC_STAT> snapshot;
    RshUnits linear_units = RshUnits::automatic;
    RshUnits angular_units = RshUnits::automatic;
    int32_t last_serial = 0;   // of the last command this session sent
    bool sent_any = false;
    // Queue a reply line (\r\n is added).
    void reply(const std::string &line) { out += line + "\r\n"; }
};

// The whole server: options, the machine link, sessions and the shared message texts.
struct RshServer {
    explicit RshServer(const RshOptions &o, const std::string &nml) : opt(o), client(nml) {}
    RshOptions opt;
    UiClient client;
    std::string ini_path;
    std::string ini_version;       // [EMC]VERSION
    std::vector<std::string> search_path;  // --path, the working directory, PROGRAM_PREFIX, ~/nc_files
    double default_spindle_speed = 0;       // [DISPLAY]DEFAULT_SPINDLE_SPEED
    long debug = 0;                // [EMC]DEBUG, then what 'set debug' sent
    std::vector<int> listeners;
    std::vector<std::unique_ptr<RshSession>> sessions;
    int next_id = 1;
    int enabled_id = 0;            // session holding control (set enable), 0 none
    std::string error_text, operator_text, operator_display;
    std::string last_opened;       // file of the last 'set open'
    int program_start_line = 0;    // line of the last 'set run'
    bool shutdown = false;         // 'shutdown' received: leave the loop
};

// How a get/set handler ended.
enum class RshResult {
    ok,       // get: reply written; set: ACK when verbose
    nak,      // "GET X NAK" / "SET X NAK"
    replied,  // the handler wrote its own error line
};

// The words after get/set: args[0] is the subcommand, line the whole request.
struct RshArgs {
    std::vector<std::string> args;
    std::string line;
    size_t count() const { return args.size() - 1; }
    const std::string &at(size_t i) const { return args[i + 1]; }
};

using RshHandler = RshResult (*)(RshServer &, RshSession &, const RshArgs &);

// One subcommand. `control`: set needs the session to hold control (set enable).
struct RshSubcommand {
    const char *name;
    RshHandler get;
    RshHandler set;
    bool control;
};

// The tables (get and set share names; a null handler makes that direction NAK).
extern const RshSubcommand rsh_session_subcommands[];
extern const RshSubcommand rsh_status_subcommands[];
extern const RshSubcommand rsh_motion_subcommands[];
extern const RshSubcommand rsh_program_subcommands[];
const RshSubcommand *rsh_find_subcommand(const std::string &name);

// Handle one request line of a session.
void rsh_handle_line(RshServer &sv, RshSession &s, const std::string &line);
// The help text of 'help [command]'.
void rsh_help(RshSession &s, const std::string &topic);

// The status a get should show (fresh, or the session's snapshot); nullptr when no
// machine publishes status.
const EMC_STAT *rsh_status(RshServer &sv, RshSession &s);
// Send a command and wait as the session asks. ok, or nak when it could not be sent,
// timed out, or task answered RCS_ERROR.
RshResult rsh_send(RshServer &sv, RshSession &s, const NMLmsg &msg);
// Read one message from emcError into the server's texts.
void rsh_update_errors(RshServer &sv);
// A file name as task should get it: absolute, else the first readable one on the search
// path; "" when it exists nowhere (callers then pass the name as given).
std::string rsh_find_file(const RshServer &sv, const std::string &name);

// Network: listen, serve until shutdown or a signal. 0 or 1 (with a message).
int rsh_listen(RshServer &sv);
int rsh_serve(RshServer &sv, const volatile std::sig_atomic_t *stop);

#endif
