// halui_main.cc: halui: command line, the HAL component, and the poll loop that turns pin changes into NML commands.
#include <time.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "halui.hh"

namespace {

// How often pins are scanned and outputs refreshed.
const double CYCLE_S = 0.01;

volatile std::sig_atomic_t stop_requested = 0;

// SIGTERM/SIGINT/SIGHUP: leave the loop after this scan.
void on_signal(int) { stop_requested = 1; }

// The usage text.
void usage(FILE *out)
{
    fprintf(out, "Usage: halui [-ini INIFILE]\n"
                 "Exports the halui.* HAL pins and commands the machine of INIFILE through NML.\n"
                 "Without -ini the INI file is $INI_FILE_NAME (set by the linuxcnc launcher).\n");
}

// The INI path from -ini/--ini, else $INI_FILE_NAME; "" after a usage error.
std::string parse_args(int argc, char **argv, bool *help)
{
    std::string ini;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if ((a == "-ini" || a == "--ini") && i + 1 < argc) {
            ini = argv[++i];
        } else if (a == "-h" || a == "--help") {
            *help = true;
            return "";
        } else {
            fprintf(stderr, "halui: unknown argument '%s'\n", a.c_str());
            usage(stderr);
            return "";
        }
    }
    if (ini.empty() && getenv("INI_FILE_NAME")) ini = getenv("INI_FILE_NAME");
    if (ini.empty()) {
        fprintf(stderr, "halui: no INI file (use -ini INIFILE)\n");
        usage(stderr);
    }
    return ini;
}

// Sleep for seconds unless a signal ends the sleep early.
void pause_s(double seconds)
{
    struct timespec ts;
    ts.tv_sec = static_cast<time_t>(seconds);
    ts.tv_nsec = static_cast<long>((seconds - ts.tv_sec) * 1e9);
    nanosleep(&ts, nullptr);
}

// One scan of every pin and the status.
void cycle(Halui &h)
{
    h.client.attach();
    h.client.poll();
    halui_buttons(h);
    halui_spindles(h);
    halui_overrides(h, ui_now_s());
    halui_gui(h);
    halui_jogging(h);
    halui_mdi(h);
    h.client.poll();
    halui_outputs(h);
}

} // namespace

// Read the INI file, join HAL, make the pins, scan until a signal.
int main(int argc, char **argv)
{
    bool help = false;
    std::string ini = parse_args(argc, argv, &help);
    if (help) {
        usage(stdout);
        return 0;
    }
    HaluiConfig cfg;
    if (ini.empty() || !halui_read_config(ini, cfg)) return 1;
    ui_install_stop_signals(on_signal);
    int comp_id = hal_init("halui");
    if (comp_id < 0) {
        fprintf(stderr, "halui: hal_init failed: %s (is realtime running?)\n", strerror(-comp_id));
        return 1;
    }
    std::unique_ptr<Halui> h(new Halui(cfg));
    h->client.set_stop_flag(&stop_requested);
    if (halui_make_pins(comp_id, cfg, h->pins) < 0) {
        hal_exit(comp_id);
        return 1;
    }
    hal_ready(comp_id);
    while (!stop_requested) {
        cycle(*h);
        pause_s(CYCLE_S);
    }
    hal_exit(comp_id);
    return 0;
}
