/* rtapi_client.c: send a command to the master, starting one on demand. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <libgen.h>
#include <limits.h>
#include <spawn.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "rtapi_client.h"
#include "rtapi_wire.h"

#define CONNECT_WAIT_MS 3000
#define REPLY_TIMEOUT_MS 60000
#define PING_TIMEOUT_MS 3000

extern char **environ;

/* Sleep ms milliseconds. */
static void sleep_ms(int ms)
{
    struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };

    nanosleep(&ts, NULL);
}

/* bin/rtapi_app beside the lib/ holding this library, else "rtapi_app" (PATH). */
static void rtapi_app_path(char *path, size_t size)
{
    Dl_info info;
    char lib[PATH_MAX];

    snprintf(path, size, "rtapi_app");
    if (!dladdr((void *)rtapi_app_path, &info) || !info.dli_fname)
        return;
    snprintf(lib, sizeof lib, "%s", info.dli_fname);
    snprintf(path, size, "%s/../bin/rtapi_app", dirname(lib));
    if (access(path, X_OK) != 0)
        snprintf(path, size, "rtapi_app");
}

/* Run `rtapi_app start` and wait for it; 0 on success. */
static int start_master(void)
{
    char path[PATH_MAX];
    char *argv[] = { "rtapi_app", "start", NULL };
    pid_t pid;
    int status;

    rtapi_app_path(path, sizeof path);
    if (posix_spawnp(&pid, path, NULL, NULL, argv, environ) != 0)
        return -ENOENT;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -ECHILD;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -ENOTCONN;
}

/* Connect, retrying for up to 3 s while the master comes up. */
static int connect_with_retry(void)
{
    int fd = rtapi_wire_connect();

    for (int waited = 0; fd < 0 && waited < CONNECT_WAIT_MS; waited += 10) {
        sleep_ms(10);
        fd = rtapi_wire_connect();
    }
    if (fd < 0)
        fprintf(stderr, "Waited 3 seconds for master.  giving up.\n");
    return fd;
}

/* Connect to the master, auto-starting one (with the deprecation warning). */
static int connect_master(int autostart)
{
    int fd = rtapi_wire_connect();

    if (fd >= 0 || !autostart)
        return fd < 0 ? -ENOTCONN : fd;
    fprintf(stderr, "WARNING: Deprecated: No active realtime environment found. "
            "Use \"realtime start\" to start one.\n"
            "  Starting rtapi_app in the background now; it keeps running until "
            "\"realtime stop\".\n");
    if (start_master() != 0)
        return -ENOTCONN;
    return connect_with_retry();
}

/* Send one request on fd and read the reply. */
static int exchange(int fd, int argc, const char *const argv[], char *reply,
                    size_t reply_size, int timeout_ms)
{
    static unsigned char buf[RTAPI_WIRE_MAX];
    int len, result = -EPROTO;

    len = rtapi_wire_encode_request(argc, argv, buf, sizeof buf);
    if (len < 0) {
        fprintf(stderr, "rtapi_app: command too long\n");
        return len;
    }
    if (rtapi_wire_send(fd, buf, (size_t)len) < 0)
        return -ECONNRESET;
    len = rtapi_wire_recv(fd, buf, sizeof buf, timeout_ms);
    if (len == -ETIMEDOUT)
        fprintf(stderr, "rtapi_app: no reply from master within %d s\n", timeout_ms / 1000);
    else if (len < 0)
        fprintf(stderr, "rtapi_app: master closed the connection without a reply\n");
    if (len < 0)
        return len;
    if (rtapi_wire_decode_reply(buf, (size_t)len, &result, reply, reply_size) < 0) {
        fprintf(stderr, "rtapi_app: malformed reply from master\n");
        return -EPROTO;
    }
    return result;
}

/* Run one command on the master (see rtapi_client.h). */
int rtapi_app_command(int argc, const char *const argv[], int autostart,
                      char *reply, size_t reply_size)
{
    int fd, result;

    if (reply && reply_size > 0)
        reply[0] = '\0';
    else
        reply_size = 0;
    fd = connect_master(autostart);
    if (fd < 0)
        return fd;
    result = exchange(fd, argc, argv, reply, reply_size,
                      argc > 0 && strcmp(argv[0], "ping") == 0 ? PING_TIMEOUT_MS
                                                               : REPLY_TIMEOUT_MS);
    close(fd);
    return result;
}

/* Ping the master. */
int rtapi_app_running(void)
{
    const char *argv[] = { "ping" };

    return rtapi_app_command(1, argv, 0, NULL, 0) == 0;
}

/* Master pid via SO_PEERCRED of a throw-away connection. */
int rtapi_app_master_pid(void)
{
    struct ucred cred;
    socklen_t len = sizeof cred;
    int fd = rtapi_wire_connect(), pid = -1;

    if (fd < 0)
        return -1;
    if (getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &cred, &len) == 0)
        pid = (int)cred.pid;
    close(fd);
    return pid;
}
