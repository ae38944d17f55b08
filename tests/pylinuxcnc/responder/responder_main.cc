// responder_main.cc: nml_responder -ini INI: plays task's side of emcCommand/emcStatus/emcError at [TASK]CYCLE_TIME.
#include <signal.h>
#include <time.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "inifile.hh"
#include "responder.hh"

namespace {

volatile sig_atomic_t stop_requested = 0;

// SIGTERM/SIGINT: leave the loop.
void on_signal(int)
{
    stop_requested = 1;
}

// Monotonic seconds.
double mono_s()
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

// Sleep until an absolute monotonic time.
void sleep_until(double t)
{
    struct timespec ts;
    ts.tv_sec = static_cast<time_t>(t);
    ts.tv_nsec = static_cast<long>((t - ts.tv_sec) * 1e9);
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
}

// Open the three buffers as process emc; false with a message.
bool open_channels(Machine &m)
{
    std::string err;
    m.cmd = EmcChannel::open(m.cfg.nml_file, "emcCommand", "emc", &err);
    if (m.cmd) m.stat = EmcChannel::open(m.cfg.nml_file, "emcStatus", "emc", &err);
    if (m.stat) m.err = EmcChannel::open(m.cfg.nml_file, "emcError", "emc", &err);
    if (!m.err) {
        fprintf(stderr, "nml_responder: %s\n", err.c_str());
        return false;
    }
    char terr[256];
    m.tools = tooldata_open(0, terr, sizeof terr);
    if (!m.tools) {
        fprintf(stderr, "nml_responder: %s\n", terr);
        return false;
    }
    return true;
}

// What task reports right after startup (nml.md sec. 5, python.md).
void set_startup_status(Machine &m)
{
    static const int32_t gcodes[STATE_TAG_GCODES] = {0, 800, -1, 170, 400, 200, 900, 940, 540,
                                                     490, 990, 640, -1, 970, 911, 80, -1};
    static const int32_t mcodes[STATE_TAG_MCODES] = {0, -1, 5, -1, 9, -1, 48, -1, 53, -1};
    memcpy(m.status.task.activeGCodes, gcodes, sizeof gcodes);
    memcpy(m.status.task.activeMCodes, mcodes, sizeof mcodes);
    m.status.task.activeSettings[3] = 0.001;
    m.status.motion.traj.maxVelocity = m.cfg.max_velocity;
    for (int s = 0; s < m.cfg.spindles; s++) m.status.motion.spindle[s].brake = 1;
}

// Read at most one command per cycle, as task does.
void read_command(Machine &m)
{
    const NMLmsg *msg = m.cmd->read();
    if (msg) {
        responder_handle(m, *msg);
    } else if (!m.cmd->error().empty()) {
        fprintf(stderr, "nml_responder: %s\n", m.cmd->error().c_str());
    }
}

// The cycle: command, simulation, status; at the configured period.
int run(Machine &m)
{
    double next = mono_s();
    m.now = next;
    responder_publish_status(m);
    while (!stop_requested) {
        next += m.cfg.cycle_s;
        sleep_until(next);
        double now = mono_s();
        if (now - next > 1.0) next = now; // the machine was suspended: do not catch up
        double dt = now - m.now;
        m.now = now;
        if (!m.cmd->alive()) {
            fprintf(stderr, "nml_responder: the NML buffers were removed; exiting\n");
            return 1;
        }
        read_command(m);
        responder_advance(m, dt);
        responder_publish_status(m);
    }
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    std::string ini;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-ini") && i + 1 < argc) ini = argv[++i];
        else {
            fprintf(stderr, "usage: nml_responder -ini INIFILE\n");
            return 1;
        }
    }
    if (ini.empty()) {
        fprintf(stderr, "usage: nml_responder -ini INIFILE\n");
        return 1;
    }
    Machine m;
    if (!responder_load_config(ini, m.cfg) || !open_channels(m)) return 1;
    set_startup_status(m);
    if (!m.cfg.tool_table.empty() && !responder_load_tools(m, m.cfg.tool_table)) return 1;
    if (m.cfg.tool_table.empty()) responder_publish_tools(m);
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
    int rc = run(m);
    tooldata_close(m.tools);
    return rc;
}
