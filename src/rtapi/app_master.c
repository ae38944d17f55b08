/* app_master.c: the rtapi_app master: start-up, one connection at a time, shutdown. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>
#include "app.h"
#include "rtapi.h"
#include "rtapi_internal.h"

#define RECV_TIMEOUT_MS 10000

static volatile sig_atomic_t stop_signal;

/* SIGTERM/SIGINT: remember, so the accept loop shuts down cleanly. */
static void on_stop_signal(int sig)
{
    stop_signal = sig;
}

/* Fatal signals: say which, then die with the default action. */
static void on_fatal_signal(int sig)
{
    char msg[64];
    int n = snprintf(msg, sizeof msg, "rtapi_app: %s - aborting\n", sigabbrev_np(sig));

    if (write(2, msg, (size_t)n) < 0)
        n = 0;
    signal(sig, SIG_DFL);
    raise(sig);
}

/* Install the master's signal handlers (no SA_RESTART so accept() is woken). */
static void install_signals(void)
{
    struct sigaction sa;

    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGINT, &sa, NULL);
    sa.sa_handler = on_fatal_signal;
    sigaction(SIGSEGV, &sa, NULL);
    sigaction(SIGILL, &sa, NULL);
    sigaction(SIGFPE, &sa, NULL);
    sigaction(SIGXCPU, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);
    signal(SIGTSTP, SIG_IGN);
}

/* Non-zero when the connected client's stderr is the same file as ours. */
static int peer_shares_stderr(int fd)
{
    struct ucred cred;
    socklen_t len = sizeof cred;
    struct stat ours, theirs;
    char path[64];

    if (getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &cred, &len) != 0)
        return 0;
    snprintf(path, sizeof path, "/proc/%d/fd/2", (int)cred.pid);
    if (fstat(2, &ours) != 0 || stat(path, &theirs) != 0)
        return 0;
    return ours.st_dev == theirs.st_dev && ours.st_ino == theirs.st_ino;
}

/* Unload everything (newest first, hal_lib last) and delete leftover tasks. */
static void shut_down(void)
{
    rtapi_tasks_lock();
    app_unload_all();
    for (int id = 0; id < RTAPI_MAX_TASKS; id++)
        rtapi_task_delete(id);
    rtapi_tasks_unlock();
    rtapi_msg_flush();
}

/* Read, run and answer one request; a broken request is dropped. */
static void serve_connection(int fd, int *exit_requested)
{
    static unsigned char msg[RTAPI_WIRE_MAX];
    static char store[RTAPI_WIRE_MAX];
    static char *argv[RTAPI_WIRE_MAX_ARGS + 1];
    static app_reply_t reply;
    int len, argc, result;

    len = rtapi_wire_recv(fd, msg, sizeof msg, RECV_TIMEOUT_MS);
    if (len < 0) {
        if (len != -ECONNRESET)
            fprintf(stderr, "rtapi_app: dropped a request: %s\n", strerror(-len));
        return;
    }
    argc = rtapi_wire_decode_request(msg, (size_t)len, store, argv, RTAPI_WIRE_MAX_ARGS);
    if (argc < 0) {
        fprintf(stderr, "rtapi_app: dropped a malformed request\n");
        return;
    }
    reply.len = 0;
    reply.text[0] = '\0';
    reply.peer_shares_stderr = peer_shares_stderr(fd);
    result = app_dispatch(&reply, argc, argv, exit_requested);
    if (*exit_requested)
        shut_down();
    fflush(stdout);
    fflush(stderr);
    len = rtapi_wire_encode_reply(result, reply.text, msg, sizeof msg);
    rtapi_wire_send(fd, msg, (size_t)len);
}

/* Route stdin to /dev/null and start a new session. */
static void detach(void)
{
    int fd = open("/dev/null", O_RDONLY);

    if (fd >= 0) {
        dup2(fd, 0);
        if (fd != 0)
            close(fd);
    }
    setsid();
}

/* Load hal_lib first; 0 or -1. */
static int start_up(void)
{
    static app_reply_t reply;
    char *argv[] = { "hal_lib", NULL };

    reply.peer_shares_stderr = 1;
    setvbuf(stdout, NULL, _IOLBF, 0);
    install_signals();
    rtapi_rt_announce();
    rtapi_rt_harden();
    app_preload_hal_library();
    rtapi_tasks_lock();
    if (app_load(&reply, 1, argv) < 0) {
        rtapi_tasks_unlock();
        fprintf(stderr, "rtapi_app: could not load hal_lib; master not started\n");
        return -1;
    }
    rtapi_tasks_unlock();
    return 0;
}

/* Master main loop: serve one connection at a time until exit or SIGTERM. */
int app_master_run(int listen_fd)
{
    int exit_requested = 0;

    detach();
    if (start_up() < 0)
        return 1;
    while (!exit_requested && !stop_signal) {
        int fd = accept4(listen_fd, NULL, NULL, SOCK_CLOEXEC);
        if (fd < 0) {
            if (errno != EINTR && errno != ECONNABORTED)
                perror("rtapi_app: accept");
            continue;
        }
        serve_connection(fd, &exit_requested);
        close(fd);
    }
    if (stop_signal)
        fprintf(stderr, "rtapi_app: %s - shutting down\n", sigabbrev_np(stop_signal));
    close(listen_fd);
    shut_down();
    return 0;
}
