// rsh_main.cc: linuxcncrsh: options, the INI keys it reads, signals, and the server's life.
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "inifile.hh"
#include "rsh.hh"
#include "rsh_format.hh"

namespace {

volatile std::sig_atomic_t stop_requested = 0;

// SIGTERM/SIGINT/SIGHUP: stop serving.
void on_signal(int) { stop_requested = 1; }

const char USAGE[] =
    "Usage: linuxcncrsh [OPTIONS] [-- -ini INIFILE]\n"
    "Text-mode interface to LinuxCNC over TCP (telnet/nc), LinuxCNC's protocol.\n"
    "  -p, --port PORT          TCP port (default 5007)\n"
    "  -n, --name NAME          server name in HELLO ACK (default EMCNETSVR)\n"
    "  -w, --connectpw PW       password of HELLO (default EMC)\n"
    "  -e, --enablepw PW        password of SET ENABLE (default EMCTOO)\n"
    "  -s, --sessions N         most simultaneous connections (default 0: no limit)\n"
    "  -d, --path DIR[:DIR...]  where relative file names (open, load_tool_table) are looked up\n"
    "  -b, --bind ADDRESS       listen on ADDRESS (repeatable; default 127.0.0.1 and ::1);\n"
    "                           other than loopback only with your own passwords\n"
    "  -q, --quiet              no connection messages on stdout\n"
    "  -h, --help               this text\n"
    "  -ini INIFILE             the configuration (default $INI_FILE_NAME, else emc.ini)\n";

// Option name and value: "--port 5007", "--port=5007", "-p 5007". false at the end.
bool option_value(int argc, char **argv, int *i, const std::string &a, std::string *value)
{
    size_t eq = a.find('=');
    if (a.compare(0, 2, "--") == 0 && eq != std::string::npos) {
        *value = a.substr(eq + 1);
        return true;
    }
    if (*i + 1 >= argc) return false;
    *value = argv[++*i];
    return true;
}

// The option a word names (long form), "" for none.
std::string option_name(const std::string &a)
{
    static const char *const pairs[][2] = {{"-p", "--port"},          {"-n", "--name"},
                                           {"-w", "--connectpw"},     {"-e", "--enablepw"},
                                           {"-s", "--sessions"},      {"-d", "--path"},
                                           {"-b", "--bind"},          {"-ini", "--ini"}};
    std::string key = a.substr(0, a.find('='));
    for (const auto &p : pairs)
        if (key == p[0] || key == p[1]) return p[1];
    return "";
}

// Store one option with a value; false with a message when the value is bad.
bool store(RshOptions &o, const std::string &name, const std::string &v)
{
    long n;
    if (name == "--port") {
        if (!rsh_parse_int(v, &n) || n < 1 || n > 65535) {
            fprintf(stderr, "linuxcncrsh: --port '%s' is not a port number (1-65535)\n", v.c_str());
            return false;
        }
        o.port = static_cast<int>(n);
    } else if (name == "--sessions") {
        if (!rsh_parse_int(v, &n) || n < -1) {
            fprintf(stderr, "linuxcncrsh: --sessions '%s' is not a number of sessions\n", v.c_str());
            return false;
        }
        o.max_sessions = static_cast<int>(n);
    } else if (name == "--name") o.name = v;
    else if (name == "--connectpw") o.connect_pw = v;
    else if (name == "--enablepw") o.enable_pw = v;
    else if (name == "--bind") o.bind.push_back(v);
    else if (name == "--ini") o.ini = v;
    else if (name == "--path") {
        for (size_t start = 0; start <= v.size();) {
            size_t colon = v.find(':', start);
            std::string dir = v.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
            if (!dir.empty()) o.path.push_back(IniFile::TildeExpand(dir));
            if (colon == std::string::npos) break;
            start = colon + 1;
        }
    }
    return true;
}

// The INI keys: NML file, [EMC]VERSION and DEBUG, program directory, spindle speed.
bool read_ini(RshServer *&sv, const RshOptions &opt)
{
    IniFile ini;
    if (!ini.Open(opt.ini)) {
        fprintf(stderr, "linuxcncrsh: %s: %s\n", opt.ini.c_str(), ini.ErrorText().c_str());
        return false;
    }
    std::string why;
    std::string nml = emc_nml_file_for_ini(opt.ini, &why);
    if (nml.empty()) {
        fprintf(stderr, "linuxcncrsh: %s\n", why.c_str());
        return false;
    }
    sv = new RshServer(opt, nml);
    char cwd[4096];
    sv->ini_path = opt.ini[0] == '/' || !getcwd(cwd, sizeof cwd) ? opt.ini : std::string(cwd) + "/" + opt.ini;
    sv->ini_version = ini.Find("VERSION", "EMC").value_or("");
    if (std::optional<long long> d = ini.FindInt("DEBUG", "EMC")) sv->debug = static_cast<long>(*d);
    if (std::optional<double> d = ini.FindReal("DEFAULT_SPINDLE_SPEED", "DISPLAY")) sv->default_spindle_speed = *d;
    sv->search_path = opt.path;
    if (getcwd(cwd, sizeof cwd)) sv->search_path.push_back(cwd);
    if (std::optional<std::string> p = ini.Find("PROGRAM_PREFIX", "DISPLAY")) sv->search_path.push_back(IniFile::TildeExpand(*p));
    if (getenv("HOME")) sv->search_path.push_back(std::string(getenv("HOME")) + "/nc_files");
    return true;
}

} // namespace

// Parse the command line (LinuxCNC's options, then "-- -ini FILE").
int rsh_parse_options(int argc, char **argv, RshOptions &o)
{
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i], value;
        if (a == "--") continue;
        if (a == "-h" || a == "--help") return 2;
        if (a == "-q" || a == "--quiet") {
            o.quiet = true;
            continue;
        }
        std::string name = option_name(a);
        if (name.empty() || !option_value(argc, argv, &i, a, &value)) {
            fprintf(stderr, "linuxcncrsh: %s '%s'\n%s", name.empty() ? "unknown option" : "missing value of",
                    a.c_str(), USAGE);
            return 1;
        }
        if (!store(o, name, value)) return 1;
    }
    if (o.ini.empty()) o.ini = getenv("INI_FILE_NAME") ? getenv("INI_FILE_NAME") : "emc.ini";
    return 0;
}

// Options, INI file, listening sockets, then serve until shutdown or a signal.
int main(int argc, char **argv)
{
    RshOptions opt;
    int rc = rsh_parse_options(argc, argv, opt);
    if (rc == 2) fputs(USAGE, stdout);
    if (rc) return rc == 2 ? 0 : 1;
    setvbuf(stdout, nullptr, _IOLBF, 0);
    RshServer *sv = nullptr;
    if (!read_ini(sv, opt)) return 1;
    std::unique_ptr<RshServer> server(sv);
    ui_install_stop_signals(on_signal);
    signal(SIGPIPE, SIG_IGN);   // a vanished client must not kill the server
    server->client.set_stop_flag(&stop_requested);
    if (rsh_listen(*server) != 0) return 1;
    return rsh_serve(*server, &stop_requested);
}
