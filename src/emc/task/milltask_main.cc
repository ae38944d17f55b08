// milltask_main.cc: milltask -ini INI: read the configuration, run the task cycle until SIGTERM/SIGINT.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <unistd.h>

#include "task.hh"

namespace {
volatile sig_atomic_t stop_requested = 0;
void on_signal(int) { stop_requested = 1; }

int usage(FILE *out, int status)
{
    fprintf(out, "usage: milltask -ini INIFILE\n"
                 "The task controller linuxcnc starts as [TASK]TASK (halcmd loadusr -Wn inihal milltask -ini INI):\n"
                 "state machine, interpreter, io control (HAL iocontrol.0) and inihal. See milltask(1).\n");
    return status;
}
}  // namespace

int main(int argc, char **argv)
{
    std::string ini;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return usage(stdout, 0);
        if ((!strcmp(argv[i], "-ini") || !strcmp(argv[i], "--ini")) && i + 1 < argc) ini = argv[++i];
        else return usage(stderr, 1);
    }
    if (ini.empty()) return usage(stderr, 1);
    MachineConfig cfg;
    std::vector<std::string> errors;
    if (!machine_config_read(ini, cfg, &errors)) {
        for (const std::string &e : errors) fprintf(stderr, "milltask: %s\n", e.c_str());
        return 1;
    }
    struct sigaction sa = {};
    sa.sa_handler = on_signal;
    sigaction(SIGTERM, &sa, nullptr);
    sigaction(SIGINT, &sa, nullptr);
    signal(SIGPIPE, SIG_IGN);
    Task task(cfg);
    std::string error;
    if (!task.init(&error)) {
        fprintf(stderr, "milltask: %s\n", error.c_str());
        task.shutdown();
        return 1;
    }
    int rc = 0;
    while (!stop_requested) {
        if (!task.cycle()) { rc = 1; break; }
        task.wait_next_cycle();
    }
    task.shutdown();
    return rc;
}
