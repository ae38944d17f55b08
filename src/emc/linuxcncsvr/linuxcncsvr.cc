// linuxcncsvr.cc: the NML master: creates a configuration's buffers and tool-data segment, removes them on exit.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "emc_channel.hh"
#include "nml.h"
#include "rtapi_instance.h"
#include "tooldata.h"

namespace {

const char USAGE[] =
    "Usage: linuxcncsvr -ini INIFILE [--daemon] [--ready-file FILE]\n"
    "       linuxcncsvr -nml NMLFILE [--daemon] [--ready-file FILE]\n"
    "       linuxcncsvr (-ini INIFILE | -nml NMLFILE) --list\n"
    "Creates the NML buffers of the configuration ([EMC]NML_FILE, default\n"
    "configs/common/linuxcnc.nml) and the tool-data segment, and removes them on\n"
    "SIGTERM, SIGINT or SIGHUP. It serves nothing on the network.\n"
    "  --daemon          detach once everything exists; the parent prints the pid and exits 0\n"
    "  --ready-file FILE write the pid to FILE once everything exists (removed on exit)\n"
    "  --list            print the buffers and this instance's keys, create nothing\n";

// Command line.
struct Options {
    std::string ini;
    std::string nml;
    std::string ready_file;
    bool daemon = false;
    bool list = false;
};

// Parse argv; false (after a message) on a bad command line.
bool parse_args(int argc, char **argv, Options &o)
{
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        bool has_value = i + 1 < argc;
        if ((a == "-ini" || a == "--ini") && has_value) o.ini = argv[++i];
        else if ((a == "-nml" || a == "--nml") && has_value) o.nml = argv[++i];
        else if (a == "--ready-file" && has_value) o.ready_file = argv[++i];
        else if (a == "--daemon" || a == "-d") o.daemon = true;
        else if (a == "--list") o.list = true;
        else if (a == "-h" || a == "--help") {
            fputs(USAGE, stdout);
            exit(0);
        } else {
            fprintf(stderr, "linuxcncsvr: unexpected argument '%s'\n%s", a.c_str(), USAGE);
            return false;
        }
    }
    if (o.ini.empty() == o.nml.empty()) {
        fprintf(stderr, "linuxcncsvr: give exactly one of -ini INIFILE or -nml NMLFILE\n%s", USAGE);
        return false;
    }
    return true;
}

// Everything the master holds.
struct Served {
    std::vector<nml_channel_t *> channels;
    tooldata_t *tooldata = nullptr;
    std::string ready_file;

    // Remove what was created (only that) and the ready file.
    ~Served()
    {
        for (nml_channel_t *ch : channels) nml_close(ch);
        tooldata_close(tooldata);
        if (!ready_file.empty()) unlink(ready_file.c_str());
    }
};

// Print the buffers of the file and the keys this instance uses.
void list_buffers(const nml_config_t *cfg)
{
    printf("%-16s %-10s %8s  %s\n", "buffer", "key", "size", "options");
    for (int i = 0; i < cfg->n_buffers; i++) {
        const nml_buffer_cfg_t *b = &cfg->buffers[i];
        printf("%-16s 0x%08x %8u %s%s%s\n", b->name, (unsigned)nml_buffer_key(b), b->size,
               b->flags & NML_FLAG_QUEUE ? " queue" : "",
               b->flags & NML_FLAG_CONFIRM_WRITE ? " confirm_write" : "",
               b->flags & NML_FLAG_SERIAL ? " serial" : "");
    }
    printf("%-16s 0x%08x\n", "(tool data)", (unsigned)rtapi_instance_key(TOOLDATA_BASE_KEY));
}

// Create every buffer whose emcsvr line makes it master, then the tool data. 0 or -1.
int create_all(const nml_config_t *cfg, Served &s)
{
    char err[512];
    for (int i = 0; i < cfg->n_buffers; i++) {
        const nml_buffer_cfg_t *b = &cfg->buffers[i];
        const nml_process_cfg_t *p = nml_config_process(cfg, "emcsvr", b->name);
        if (!p || !p->master) {
            fprintf(stderr, "linuxcncsvr: %s: buffer '%s' is not created here (process "
                            "emcsvr has no master P line for it)\n", cfg->path, b->name);
            continue;
        }
        nml_channel_t *ch = nml_open_config(cfg, b->name, "emcsvr", err, sizeof err);
        if (!ch) {
            fprintf(stderr, "linuxcncsvr: %s\n", err);
            return -1;
        }
        s.channels.push_back(ch);
    }
    s.tooldata = tooldata_open(1, err, sizeof err);
    if (!s.tooldata) {
        fprintf(stderr, "linuxcncsvr: %s\n", err);
        return -1;
    }
    return 0;
}

// Write the pid to the ready file through a temporary file and rename. 0 or -1.
int write_ready_file(const std::string &path)
{
    std::string tmp = path + ".tmp" + std::to_string(getpid());
    FILE *f = fopen(tmp.c_str(), "w");
    if (!f || fprintf(f, "%d\n", (int)getpid()) < 0 || fclose(f) != 0 ||
        rename(tmp.c_str(), path.c_str()) != 0) {
        fprintf(stderr, "linuxcncsvr: cannot write ready file %s: %s\n", path.c_str(),
                strerror(errno));
        unlink(tmp.c_str());
        return -1;
    }
    return 0;
}

// A daemon drops stderr once ready, so nobody capturing the parent's output waits for it.
void quiet_stderr()
{
    int null_fd = ::open("/dev/null", O_WRONLY);
    if (null_fd >= 0) {
        dup2(null_fd, 2);
        close(null_fd);
    }
}

// Create, announce readiness (ready file, daemon pipe), wait for a stop signal, clean up.
int serve(const nml_config_t *cfg, const Options &o, int ready_fd)
{
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGTERM);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGHUP);
    sigprocmask(SIG_BLOCK, &stop, nullptr);
    int rc = 0;
    {
        Served s;
        if (create_all(cfg, s) < 0 ||
            (!o.ready_file.empty() && write_ready_file(o.ready_file) < 0)) {
            rc = 1;
        } else {
            s.ready_file = o.ready_file;
            if (ready_fd >= 0) {
                signal(SIGPIPE, SIG_IGN);
                if (::write(ready_fd, "R", 1) != 1) rc = 1;
                close(ready_fd);
                ready_fd = -1;
                quiet_stderr();
            }
            int sig = 0;
            while (rc == 0 && sigwait(&stop, &sig) != 0) {}
        }
    }
    if (ready_fd >= 0) close(ready_fd);
    return rc;
}

// Fork; the parent waits for the child to be ready, prints its pid and exits.
int daemonize(const nml_config_t *cfg, const Options &o)
{
    int fds[2];
    if (pipe(fds) < 0) {
        perror("linuxcncsvr: pipe");
        return 1;
    }
    pid_t pid = fork();
    if (pid < 0) {
        perror("linuxcncsvr: fork");
        return 1;
    }
    if (pid == 0) {
        close(fds[0]);
        setsid();
        int null_fd = ::open("/dev/null", O_RDWR);
        if (null_fd >= 0) {
            dup2(null_fd, 0);
            dup2(null_fd, 1); // a caller reading our stdout ($(linuxcncsvr --daemon)) gets EOF
        }
        if (null_fd > 1) close(null_fd);
        return serve(cfg, o, fds[1]);
    }
    close(fds[1]);
    char c = 0;
    ssize_t n;
    while ((n = ::read(fds[0], &c, 1)) < 0 && errno == EINTR) {}
    if (n != 1) return 1; // the child reported its error on stderr and exited
    printf("%d\n", (int)pid);
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    Options o;
    if (!parse_args(argc, argv, o)) return 1;
    std::string err;
    std::string nml = o.nml.empty() ? emc_nml_file_for_ini(o.ini, &err) : o.nml;
    if (nml.empty()) {
        fprintf(stderr, "linuxcncsvr: %s\n", err.c_str());
        return 1;
    }
    char perr[512];
    nml_config_t *cfg = nml_config_load(nml.c_str(), perr, sizeof perr);
    if (!cfg) {
        fprintf(stderr, "linuxcncsvr: %s\n", perr);
        return 1;
    }
    for (int i = 0; i < cfg->n_warnings; i++) fprintf(stderr, "linuxcncsvr: %s\n", cfg->warnings[i]);
    int rc;
    if (o.list) {
        list_buffers(cfg);
        rc = 0;
    } else {
        fflush(stdout);
        rc = o.daemon ? daemonize(cfg, o) : serve(cfg, o, -1);
    }
    nml_config_free(cfg);
    return rc;
}
