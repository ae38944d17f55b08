/* halcmd_cmd_usr.c: loadusr, waitusr and unloadusr (user-space components). */
#include <errno.h>
#include <getopt.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"
#include "halcmd_hal.h"

/* Options of one loadusr command. */
typedef struct {
    int wait_ready, wait_exit, ignore_status;
    char name[HAL_NAME_LEN + 1];
} hc_usr_opts_t;

/* Sleep for ms milliseconds. */
static void hc_sleep_ms(long ms)
{
    struct timespec ts = {ms / 1000, (ms % 1000) * 1000000L};
    nanosleep(&ts, NULL);
}

/* Parse loadusr's own options; returns the index of the program or -1 (reported). */
static int hc_usr_options(int argc, char *argv[], hc_usr_opts_t *o)
{
    char *av[HC_MAX_TOKENS + 2];
    int c;
    av[0] = "loadusr";
    for (int i = 0; i < argc; i++)
        av[i + 1] = argv[i];
    av[argc + 1] = NULL;
    optind = 0;
    opterr = 0;
    while ((c = getopt(argc + 1, av, "+wWin:")) != -1) {
        if (c == 'w') o->wait_exit = 1;
        else if (c == 'W') o->wait_ready = 1;
        else if (c == 'i') o->ignore_status = 1;
        else if (c == 'n') snprintf(o->name, sizeof o->name, "%s", optarg);
        else if (optopt == 'n') {
            hc_error("loadusr: option -n needs a component name");
            return -1;
        } else {
            hc_error("loadusr: unknown option '-%c'", optopt);
            return -1;
        }
    }
    if (optind - 1 >= argc) {
        hc_error("loadusr: no program given (usage: loadusr [-W] [-w] [-i] [-n name] program [args...])");
        return -1;
    }
    return optind - 1;
}

/* Default component name: basename of prog without its last extension. */
static void hc_default_name(const char *prog, char *name, size_t size)
{
    const char *base = strrchr(prog, '/');
    char *dot;
    snprintf(name, size, "%s", base ? base + 1 : prog);
    dot = strrchr(name, '.');
    if (dot && dot != name)
        *dot = '\0';
}

/* Fork and exec prog with its args; returns the child pid or -1. */
static pid_t hc_spawn(int argc, char *argv[])
{
    char *av[HC_MAX_TOKENS + 1];
    pid_t pid;
    for (int i = 0; i < argc; i++)
        av[i] = argv[i];
    av[argc] = NULL;
    hc_hal_fork_cost();
    fflush(NULL);
    pid = fork();
    if (pid == 0) {
        execvp(av[0], av);
        fprintf(stderr, "%s:%d: execv(%s): %s\n", hc.file ? hc.file : "<commandline>", hc.line,
                av[0], strerror(errno));
        _exit(1);
    }
    if (pid < 0)
        hc_error("fork failed: %s", strerror(errno));
    return pid;
}

/* Is the named component present and ready? */
static int hc_comp_ready(const char *name)
{
    hal_comp_info_t info;
    return hal_comp_by_name(name, &info) == 0 && info.ready;
}

/* Poll until the component is ready or the child exits (-W). */
static int hc_wait_ready(pid_t pid, const char *prog, const char *name)
{
    int status, ticks = 0;
    for (;; ticks++) {
        if (hc_comp_ready(name))
            break;
        if (waitpid(pid, &status, WNOHANG) == pid) {
            if (ticks >= 100)
                fprintf(stderr, "\n");
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
                hc_error("waitpid failed %s %s", prog, name);
            hc_error("%s exited without becoming ready", prog);
            return -1;
        }
        if (ticks == 200)
            fprintf(stderr, "Waiting for component '%s' to become ready.", name);
        else if (ticks > 200 && ticks % 10 == 0)
            fprintf(stderr, ".");
        hc_sleep_ms(10);
    }
    if (ticks >= 100)
        fprintf(stderr, "\n");
    hc_info("Component '%s' ready", name);
    return 0;
}

/* Wait for the child to exit and judge its status (-w). */
static int hc_wait_exit(pid_t pid, const char *prog, int ignore_status)
{
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    if (!WIFEXITED(status)) {
        hc_error("program '%s' did not exit normally", prog);
        return -1;
    }
    if (WEXITSTATUS(status) != 0 && !ignore_status) {
        hc_error("program '%s' failed, returned %d", prog, WEXITSTATUS(status));
        return -1;
    }
    return 0;
}

/* loadusr [-w] [-W] [-i] [-n name] prog [args] */
int hc_cmd_loadusr(int argc, char *argv[])
{
    hc_usr_opts_t o = {0};
    int first = hc_usr_options(argc, argv, &o);
    pid_t pid;
    if (hal_get_lock() & HAL_LOCK_LOAD) {
        hc_error("HAL is locked, loading of programs is not permitted");
        return -1;
    }
    if (first < 0)
        return -1;
    if (!o.name[0])
        hc_default_name(argv[first], o.name, sizeof o.name);
    pid = hc_spawn(argc - first, argv + first);
    if (pid < 0)
        return -1;
    if (o.wait_ready && hc_wait_ready(pid, argv[first], o.name) < 0)
        return -1;
    if (o.wait_exit)
        return hc_wait_exit(pid, argv[first], o.ignore_status);
    return 0;
}

/* waitusr name: wait until a user component disappears. */
int hc_cmd_waitusr(int argc, char *argv[])
{
    hal_comp_info_t info;
    (void)argc;
    if (hal_comp_by_name(argv[0], &info) < 0)
        return 0;
    if (info.type != HAL_COMP_USER) {
        hc_error("'%s' is not a userspace component", argv[0]);
        return -1;
    }
    while (hal_comp_by_name(argv[0], &info) == 0) {
        if (!info.owner_alive)
            break;
        waitpid(-1, NULL, WNOHANG);
        hc_sleep_ms(200);
    }
    return 0;
}

/* Send SIGTERM to one user component's process (never to halcmd itself); a component whose
   process is gone (killed before it could leave HAL) is removed here instead. */
static void hc_term_comp(const char *name)
{
    hal_comp_info_t info;
    if (hal_comp_by_name(name, &info) < 0 || info.type != HAL_COMP_USER)
        return;
    if (!info.owner_alive) {
        if (hal_comp_remove_orphan(name) == 0)
            hc_warning("component '%s': its process %d no longer exists; removed it from HAL",
                       name, info.pid);
        return;
    }
    if (info.pid > 0 && info.pid != getpid())
        kill(info.pid, SIGTERM);
}

/* unloadusr name|all: SIGTERM user components; always succeeds. */
int hc_cmd_unloadusr(int argc, char *argv[])
{
    char **names = NULL;
    int count = 0;
    (void)argc;
    if (strcmp(argv[0], "all") != 0) {
        hc_term_comp(argv[0]);
        return 0;
    }
    hc_hal_comp_names(HAL_COMP_USER, &names, &count);
    for (int i = 0; i < count; i++) {
        hc_term_comp(names[i]);
        free(names[i]);
    }
    free(names);
    return 0;
}
