// rs274.cc: the standalone interpreter program: runs a G-code file and prints canon calls (LinuxCNC rs274's output).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <getopt.h>
#include <memory>
#include <string>
#include <unistd.h>

#include "inifile.hh"
#include "interp.hh"
#include "sai_canon.hh"
#include "tooltable.hh"

namespace {

// Options of one run.
struct Options {
    std::string tool_file, var_file, ini_file, input, output, plugin;
    bool tool_given = false;
    int on_error = 2;
    bool block_delete = false, go = false, task = false, stack = false;
};

// print usage and exit (status 1 after a usage error, 0 for --help on stdout)
[[noreturn]] void usage(const char *prog, int status = 1)
{
    fprintf(status ? stderr : stdout,
            "Usage: %s [-p interp.so] [-t tool.tbl] [-v var-file.var] [-n 0|1|2]\n"
            "          [-b] [-s] [-g] [-i ini-file] [-T] [-l log_level] [input file [output file]]\n"
            "\n"
            "    -p: Specify the pluggable interpreter to use\n"
            "    -t: Specify the .tbl (tool table) file to use\n"
            "    -v: Specify the .var (parameter) file to use\n"
            "    -n: Specify the continue mode:\n"
            "           0: continue\n"
            "           1: enter MDI mode\n"
            "           2: stop (default)\n"
            "    -b: Toggle the 'block delete' flag (default: OFF)\n"
            "    -s: Toggle the 'print stack' flag (default: OFF)\n"
            "    -g: Toggle the 'go (batch mode)' flag (default: OFF)\n"
            "    -i: specify the .ini file (default: no ini file)\n"
            "    -T: call task_init()\n"
            "    -l: specify the log_level (default: -1)\n",
            prog);
    exit(status);
}

// directory of this executable's parent (the build tree root)
std::string tree_root()
{
    char buf[4096];
    ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) return ".";
    buf[n] = 0;
    std::string p = buf;
    p = p.substr(0, p.rfind('/'));
    return p.substr(0, p.rfind('/'));
}

// apply one command-line option (with optarg); false for a bad option or value
bool option(int c, Options &o, std::vector<CanonTool> &tools)
{
    std::string err;
    bool *toggle = c == 'b' ? &o.block_delete : c == 's' ? &o.stack : c == 'g' ? &o.go : nullptr;
    if (toggle) {
        *toggle = !*toggle;
        return true;
    }
    if (c == 'p') o.plugin = optarg;
    if (c == 'v') o.var_file = optarg;
    if (c == 'i') o.ini_file = optarg;
    if (c == 'T') o.task = true;
    if (c == 't') {
        o.tool_given = true;
        if (!load_tool_table(optarg, tools, err)) fprintf(stderr, "%s\n", err.c_str());
    }
    if (c == 'n') o.on_error = atoi(optarg);
    return strchr("ptvnbsgiTl", c) && o.on_error >= 0 && o.on_error <= 2;
}

// parse the command line; tool tables are read here (as LinuxCNC's rs274 does)
void parse_options(int argc, char **argv, Options &o, std::vector<CanonTool> &tools)
{
    int c;
    if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) usage(argv[0], 0);
    while ((c = getopt(argc, argv, "p:t:v:n:bsgi:Tl:")) != -1)
        if (!option(c, o, tools)) usage(argv[0]);
    int rest = argc - optind;
    if (rest > 2) usage(argv[0]);
    if (rest >= 1) o.input = argv[optind];
    if (rest == 2) o.output = argv[optind + 1];
}

// report an interpreter error: text, the source line, then (-s) the functions it unwound through
void report(InterpBase &in, const Options &o)
{
    fflush(stdout);
    fprintf(stderr, "%s\n%s\n", in.error_text().c_str(), in.error_line().c_str());
    if (!o.stack) return;
    for (const std::string &frame : in.error_stack()) fprintf(stderr, "%s\n", frame.c_str());
}

// run the open program to its end; returns the exit status
int run_file(InterpBase &in, const Options &o)
{
    for (;;) {
        InterpStatus st = in.execute_next();
        if (st == INTERP_EXIT) return 0;
        if (st != INTERP_ERROR) continue;
        report(in, o);
        if (o.on_error != 0 || in.at_end_of_file()) return o.on_error == 0 ? 0 : 1;
    }
}

// read MDI lines from stdin until EOF or "quit"
int run_stdin(InterpBase &in, const Options &o)
{
    char line[1024];
    bool tty = isatty(0);
    for (;;) {
        if (tty) { fprintf(stderr, "READ => "); }
        if (!fgets(line, sizeof line, stdin)) return 0;
        line[strcspn(line, "\r\n")] = 0;
        if (strcmp(line, "quit") == 0) return 0;
        if (in.execute_line(line) == INTERP_ERROR) {
            report(in, o);
            if (o.on_error == 2) return 1;
        }
    }
}

// read one answer line from stdin (without the newline); false at EOF
bool ask(const char *prompt, std::string &answer)
{
    fprintf(stderr, "%s", prompt);
    char buf[1024];
    if (!fgets(buf, sizeof buf, stdin)) return false;
    buf[strcspn(buf, "\r\n")] = 0;
    answer = buf;
    return true;
}

// the interactive menu shown without -g; returns when 1 (start) is chosen or input ends
void menu(Options &o, std::vector<CanonTool> &tools)
{
    std::string a;
    for (;;) {
        fprintf(stderr, "enter a number:\n1 = start interpreting\n2 = choose parameter file ...\n"
                        "3 = choose tool table ...\n4 = turn block delete switch %s\n"
                        "5 = adjust error handling...\n", o.block_delete ? "OFF" : "ON");
        if (!ask("enter choice => ", a) || atoi(a.c_str()) == 1) return;
        int choice = atoi(a.c_str());
        std::string err;
        if (choice == 2 && ask("name of parameter file => ", a)) o.var_file = a;
        if (choice == 3 && ask("name of tool file => ", a)) {
            tools.resize(1);
            if (!load_tool_table(a, tools, err)) fprintf(stderr, "%s\n", err.c_str());
            o.tool_given = true;
        }
        if (choice == 4) o.block_delete = !o.block_delete;
        if (choice == 5 && ask("enter a number:\n0 = continue\n1 = enter MDI mode\n2 = stop\n"
                               "enter choice => ", a))
            o.on_error = std::max(0, std::min(2, atoi(a.c_str())));
    }
}

// the built-in interpreter, or the one a plugin's make_interp() creates (nullptr on failure)
std::unique_ptr<InterpBase> make_interpreter(const std::string &plugin, Canon &canon)
{
    if (plugin.empty()) return std::make_unique<Interp>(canon);
    void *h = dlopen(plugin.c_str(), RTLD_NOW);
    if (!h && plugin.find('/') == std::string::npos)
        h = dlopen(("./" + plugin).c_str(), RTLD_NOW);
    if (!h) {
        std::string base = plugin.substr(plugin.rfind('/') + 1);
        h = dlopen((tree_root() + "/lib/" + base).c_str(), RTLD_NOW);
    }
    if (!h) {
        fprintf(stderr, "cannot load interpreter plugin %s: %s\n", plugin.c_str(), dlerror());
        return nullptr;
    }
    auto make = reinterpret_cast<MakeInterpFn>(dlsym(h, "make_interp"));
    if (!make) {
        fprintf(stderr, "interpreter plugin %s has no make_interp()\n", plugin.c_str());
        return nullptr;
    }
    return std::unique_ptr<InterpBase>(make(canon));
}

// initialise, run the file or stdin, close; returns the exit status
int run(InterpBase &in, const Options &o, const std::vector<CanonTool> &tools)
{
    in.set_tools(tools);
    in.set_task(o.task);
    in.set_block_delete(o.block_delete);
    if (!o.var_file.empty()) in.set_var_file(o.var_file);
    try {
        in.init();
    } catch (const std::exception &e) {
        fflush(stdout);
        fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    if (o.input.empty()) {
        int st = run_stdin(in, o);
        in.exit();
        return st;
    }
    try {
        in.open(o.input);
    } catch (const std::exception &e) {
        fflush(stdout);
        fprintf(stderr, "%s\n\n", e.what());
        return 1;
    }
    int st = run_file(in, o);
    in.close();
    in.exit();
    return st;
}

} // namespace

// Entry point.
int main(int argc, char **argv)
{
    Options o;
    std::vector<CanonTool> tools(1);
    parse_options(argc, argv, o, tools);
    if (!o.tool_given) {
        std::string err, path = tree_root() + "/configs/sim/sim.tbl";
        if (!load_tool_table(path, tools, err)) {
            fprintf(stderr, "%s\n", err.c_str());
            return 1;
        }
    }
    setvbuf(stdout, nullptr, _IOFBF, 1 << 16);
    setvbuf(stderr, nullptr, _IONBF, 0);
    if (!o.go) menu(o, tools);
    fprintf(stderr, "executing\n");
    FILE *out = stdout;
    if (!o.output.empty() && !(out = fopen(o.output.c_str(), "w"))) {
        fprintf(stderr, "could not open output file %s\n", o.output.c_str());
        return 1;
    }
    std::string empty;
    SaiCanon canon(out, &empty);
    std::unique_ptr<InterpBase> owned = make_interpreter(o.plugin, canon);
    if (!owned) return 1;
    InterpBase &in = *owned;
    if (!o.ini_file.empty()) {
        setenv("INI_FILE_NAME", o.ini_file.c_str(), 1);
        if (!in.load_ini(o.ini_file)) {
            fprintf(stderr, "could not open supplied INI file %s\n", o.ini_file.c_str());
            return 1;
        }
        IniFile ini(o.ini_file);
        auto units = ini.Find("LINEAR_UNITS", "TRAJ");
        canon.set_machine_mm(units && *units == "mm");
    }
    canon.set_line_source(&in.line_text());
    int status = run(in, o, tools);
    fflush(stdout);
    if (out != stdout) fclose(out);
    return status;
}
