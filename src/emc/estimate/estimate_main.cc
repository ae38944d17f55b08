// estimate_main.cc: openemc-estimate INI PROGRAM: a program's cycle time from the interpreter, canon, kinematics and planner in simulated time.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <sstream>
#include <string>
#include <unistd.h>

#include "estimate_job.hh"
#include "estimate_report.hh"
#include "inifile.hh"
#include "speed_png.hh"

namespace {

// Line ranges the report splits the program into unless --ranges says otherwise.
const int DEFAULT_RANGES = 10;

int usage(FILE *f, int rc)
{
    fprintf(f,
            "Usage: openemc-estimate [--png FILE] [--ranges N] [--quiet] INI PROGRAM\n"
            "Runs PROGRAM through the interpreter, canon, the kinematics and the trajectory\n"
            "planner of the machine INI describes, in simulated time (no HAL, no realtime),\n"
            "and prints the total cycle time, the time per tool and per line range and the\n"
            "share of feed time below 90 %% of the programmed feed.\n"
            "  --png FILE   also draw the toolpath (XY) coloured by speed into FILE\n"
            "  --ranges N   split the program into N line ranges (default %d)\n"
            "  --quiet      print only the servo-cycle counts and the simulation speed\n",
            DEFAULT_RANGES);
    return rc;
}

struct Options {
    std::string ini, program, png;
    int ranges = DEFAULT_RANGES;
    bool quiet = false;
};

// Parse the command line; -1 on a usage error, 1 for --help, else 0.
int parse(int argc, char **argv, Options &o)
{
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--help" || a == "-h") return 1;
        if (a == "--png" && i + 1 < argc) o.png = argv[++i];
        else if (a == "--ranges" && i + 1 < argc) {
            char *end;
            long n = strtol(argv[++i], &end, 10);
            if (*end || n < 1 || n > 1000) {
                fprintf(stderr, "openemc-estimate: --ranges %s: not a number from 1 to 1000\n", argv[i]);
                return -1;
            }
            o.ranges = (int)n;
        } else if (a == "--quiet") o.quiet = true;
        else if (!a.empty() && a[0] == '-') return -1;
        else if (o.ini.empty()) o.ini = a;
        else if (o.program.empty()) o.program = a;
        else return -1;
    }
    return o.ini.empty() || o.program.empty() ? -1 : 0;
}

// The identity kinematics of [KINS]KINEMATICS (trivkins and its coordinates=); false with *error
// for kinematics the estimator cannot simulate.
bool read_kins(const std::string &ini_path, kins_coords_t &coords, std::string *error)
{
    IniFile ini(ini_path);
    auto kins = ini.Find("KINEMATICS", "KINS");
    std::istringstream words(kins ? *kins : "trivkins");
    std::string module, word, letters;
    words >> module;
    while (words >> word)
        if (word.rfind("coordinates=", 0) == 0) letters = word.substr(12);
    if (module != "trivkins") {
        *error = ini_path + ": [KINS]KINEMATICS " + module + ": only trivkins (identity) kinematics are simulated";
        return false;
    }
    char why[128] = "";
    if (kins_coords_parse(letters.empty() ? nullptr : letters.c_str(), &coords, why, sizeof why) != 0) {
        *error = ini_path + ": [KINS]KINEMATICS coordinates=" + letters + ": " + why;
        return false;
    }
    return true;
}

double wall_seconds()
{
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int fail(const std::string &text)
{
    fprintf(stderr, "openemc-estimate: %s\n", text.c_str());
    return 1;
}

}  // namespace

int main(int argc, char **argv)
{
    Options o;
    int p = parse(argc, argv, o);
    if (p != 0) return p > 0 ? usage(stdout, 0) : usage(stderr, 2);
    if (access(o.ini.c_str(), R_OK) != 0) return fail(o.ini + ": " + strerror(errno));
    MachineConfig cfg;
    std::vector<std::string> errors;
    if (!machine_config_read(o.ini, cfg, &errors)) {
        for (const std::string &e : errors) fprintf(stderr, "openemc-estimate: %s\n", e.c_str());
        return 1;
    }
    kins_coords_t coords;
    std::string error;
    if (!read_kins(o.ini, coords, &error)) return fail(error);
    double t0 = wall_seconds();
    EstimateReport report(!o.png.empty());
    EstimateJob job(cfg, coords, report);
    if (!job.setup(&error) || !job.run(o.program, &error)) return fail(error);
    double wall = wall_seconds() - t0;
    if (!o.quiet) report.print(stdout, o.program, o.ranges);
    printf("servo cycles: %ld total, %ld in motion\n", report.servo_cycles(), report.motion_cycles());
    printf("simulation: %.3f s wall for %.3f s of machine time (%.0fx real time)\n", wall, report.seconds(),
           wall > 0 ? report.seconds() / wall : 0.0);
    if (!o.png.empty() && !write_speed_png(o.png, report.path(), &error)) return fail(error);
    return 0;
}
