/* app_main.c: rtapi_app command line: client commands, and `start` forking the master. */
#include <errno.h>
#include <signal.h>
#include <time.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "app.h"
#include "rtapi.h"
#include "rtapi_client.h"
#include "rtapi_wire.h"
#ifdef __SANITIZE_ADDRESS__
#include <sanitizer/lsan_interface.h>
#endif

#define REPLY_BYTES RTAPI_WIRE_MAX
#define EXIT_WAIT_TICKS 500

/* Print the usage text to out; returns status. */
static int usage(FILE *out, int status)
{
    fprintf(out, "Usage: rtapi_app start | ping | exit | check_rt | list\n"
            "       rtapi_app load <module> [name=value ...] | unload <module> ...\n"
            "       rtapi_app debug <0..5> | newinst <comp> <name> [args]\n"
            "The realtime master of instance $OPENEMC_INSTANCE (0..16777215, default 0): 'start' runs it,\n"
            "the other commands are sent to it (a missing master is started first).\n");
    return status;
}

/* Send a command to a running master (autostart as asked) and print its reply. */
static int run_command(int argc, char **argv, int autostart)
{
    static char reply[REPLY_BYTES];
    int result = rtapi_app_command(argc, (const char *const *)argv, autostart,
                                   reply, sizeof reply);

    if (reply[0])
        fputs(reply, result < 0 ? stderr : stdout);
    return result & 0xff;
}

/* Wait for a freshly forked master to answer a ping. */
static int wait_for_master(pid_t pid)
{
    const char *argv[] = { "ping" };
    int status;

    if (rtapi_app_command(1, argv, 0, NULL, 0) == 0)
        return 0;
    for (int i = 0; i < 100; i++) {
        struct timespec tick = { 0, 10 * 1000000L };
        if (waitpid(pid, &status, WNOHANG) == pid) {
            fprintf(stderr, "rtapi_app: master failed to start\n");
            return 1;
        }
        nanosleep(&tick, NULL);
    }
    fprintf(stderr, "rtapi_app: master does not answer\n");
    return 1;
}

/* End the master process. It leaves with _exit (the stdio buffers and atexit handlers
   belong to the forked parent), which skips LeakSanitizer, so an ASan build runs the
   leak check here: leaks are reported on stderr and the exit status becomes LSan's. */
static void master_exit(int status)
{
#ifdef __SANITIZE_ADDRESS__
    __lsan_do_leak_check();
#endif
    _exit(status);
}

/* `start`: bind the socket, fork+setsid a master on it, then ping it. */
static int do_start(void)
{
    int fd = rtapi_wire_listen();
    pid_t pid;
    char *argv[] = { "start", NULL };

    if (fd == -EADDRINUSE)
        return run_command(1, argv, 0);
    if (fd < 0) {
        fprintf(stderr, "rtapi_app: cannot create the master socket: %s\n", strerror(-fd));
        return 1;
    }
    fflush(stdout);
    fflush(stderr);
    pid = fork();
    if (pid < 0) {
        perror("rtapi_app: fork");
        return 1;
    }
    if (pid == 0)
        master_exit(app_master_run(fd));
    close(fd);
    return wait_for_master(pid);
}

/* Non-zero while pid exists and is not a zombie. */
static int process_alive(int pid)
{
    char path[64], state = 0;
    FILE *f;

    snprintf(path, sizeof path, "/proc/%d/stat", pid);
    f = fopen(path, "r");
    if (!f)
        return 0;
    if (fscanf(f, "%*d (%*[^)]) %c", &state) != 1)
        state = 0;
    fclose(f);
    return state != 0 && state != 'Z';
}

/* Wait up to 5 s for the master process to end; kill it if it does not. */
static int wait_for_exit(int pid)
{
    struct timespec tick = { 0, 10 * 1000000L };

    for (int i = 0; i < EXIT_WAIT_TICKS && process_alive(pid); i++)
        nanosleep(&tick, NULL);
    if (!process_alive(pid))
        return 0;
    fprintf(stderr, "ERROR: rtapi_app failed to die\n");
    kill(pid, SIGKILL);
    return 1;
}

/* `exit`: ask the master to quit and wait for it, or say that none runs. */
static int do_exit(int argc, char **argv)
{
    int pid = rtapi_app_master_pid();
    int rc;

    if (pid < 0 || !rtapi_app_running()) {
        fprintf(stderr, "rtapi_app: exit received while not running\n");
        return 0;
    }
    rc = run_command(argc, argv, 0);
    return wait_for_exit(pid) ? 1 : rc;
}

/* `check_rt`: decided in this process, never starts a master. */
static int do_check_rt(void)
{
    printf("%s\n", rtapi_realtime_type_name(rtapi_get_realtime_type()));
    return rtapi_is_realtime() ? 0 : 1;
}

/* rtapi_app entry: dispatch on the first argument. */
int main(int argc, char **argv)
{
    if (argc < 2)
        return usage(stderr, 1);
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)
        return usage(stdout, 0);
    if (argv[1][0] == '-') {
        fprintf(stderr, "rtapi_app: unknown option '%s'\n", argv[1]);
        return usage(stderr, 1);
    }
    if (strcmp(argv[1], "start") == 0)
        return do_start();
    if (strcmp(argv[1], "ping") == 0)
        return rtapi_app_running() ? 0 : 1;
    if (strcmp(argv[1], "exit") == 0)
        return do_exit(argc - 1, argv + 1);
    if (strcmp(argv[1], "check_rt") == 0)
        return do_check_rt();
    return run_command(argc - 1, argv + 1, 1);
}
