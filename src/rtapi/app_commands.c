/* app_commands.c: the master's command table (start, ping, exit, load, unload, ...). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "app.h"
#include "rtapi.h"
#include "rtapi_internal.h"

typedef int (*app_handler_t)(app_reply_t *reply, int argc, char **argv, int *exit_requested);

/* Append formatted text to the reply (silently truncated when full). */
static void reply_vappend(app_reply_t *reply, const char *fmt, va_list ap)
{
    size_t room = sizeof reply->text - reply->len;
    int n;

    if (room <= 1)
        return;
    n = vsnprintf(reply->text + reply->len, room, fmt, ap);
    if (n > 0)
        reply->len += (size_t)n < room ? (size_t)n : room - 1;
}

/* Append text for the client's stdout. */
void app_say(app_reply_t *reply, const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    reply_vappend(reply, fmt, ap);
    va_end(ap);
}

/* Log an error on our stderr; repeat it in the reply for clients elsewhere. */
void app_error(app_reply_t *reply, const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    fflush(stderr);
    va_end(ap);
    if (reply->peer_shares_stderr)
        return;
    va_start(ap, fmt);
    reply_vappend(reply, fmt, ap);
    va_end(ap);
}

/* `start` while running: just say so. */
static int cmd_start(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    (void)reply; (void)argc; (void)argv; (void)exit_requested;
    fprintf(stderr, "rtapi_app: start received while running\n");
    return 0;
}

/* `ping`: answer 0. */
static int cmd_ping(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    (void)reply; (void)argc; (void)argv; (void)exit_requested;
    return 0;
}

/* `exit`: finish after replying. */
static int cmd_exit(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    (void)reply; (void)argc; (void)argv;
    *exit_requested = 1;
    return 0;
}

/* `load <mod> [k=v ...]`. */
static int cmd_load(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    (void)exit_requested;
    return app_load(reply, argc - 1, argv + 1);
}

/* `unload <mod> ...`: every name; the result is the last failure. */
static int cmd_unload(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    int rc = 0;

    (void)exit_requested;
    if (argc < 2) {
        app_error(reply, "rtapi_app: unload: missing module name\n");
        return -1;
    }
    for (int i = 1; i < argc; i++)
        if (app_unload(reply, argv[i]) < 0)
            rc = -1;
    return rc;
}

/* `debug <0..5>`: set the master's message level. */
static int cmd_debug(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    char *end;
    long level;

    (void)exit_requested;
    if (argc < 2 || !*argv[1]) {
        app_error(reply, "Debug level is not a number\n");
        return -EINVAL;
    }
    level = strtol(argv[1], &end, 10);
    if (*end) {
        app_error(reply, "Debug level is not a number\n");
        return -EINVAL;
    }
    if (level < 0 || level > 5) {
        app_error(reply, "Debug level must be >=0 and <= 5\n");
        return -EINVAL;
    }
    rtapi_set_msg_level((int)level);
    return 0;
}

/* `newinst <comp> <name> [args]`: call HAL's instance constructor. */
static int cmd_newinst(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    int (*newinst)(const char *, const char *, int, const char **);

    (void)exit_requested;
    if (argc < 3) {
        app_error(reply, "rtapi_app: newinst: usage: newinst <comp> <name> [args]\n");
        return -EINVAL;
    }
    *(void **)&newinst = dlsym(RTLD_DEFAULT, "hal_newinst");
    if (!newinst) {
        app_error(reply, "%s: newinst: hal_lib is required, but not loaded\n", argv[1]);
        return -ENOSYS;
    }
    return newinst(argv[1], argv[2], argc - 3, (const char **)argv + 3);
}

/* `list`: loaded modules, one per line. */
static int cmd_list(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    (void)argc; (void)argv; (void)exit_requested;
    app_list(reply);
    return 0;
}

/* `check_rt`: realtime type name; 0 when realtime. */
static int cmd_check_rt(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    (void)argc; (void)argv; (void)exit_requested;
    app_say(reply, "%s\n", rtapi_realtime_type_name(rtapi_get_realtime_type()));
    return rtapi_is_realtime() ? 0 : 1;
}

static const struct {
    const char *name;
    app_handler_t handler;
} commands[] = {
    { "start", cmd_start }, { "ping", cmd_ping }, { "exit", cmd_exit },
    { "load", cmd_load }, { "unload", cmd_unload }, { "debug", cmd_debug },
    { "newinst", cmd_newinst }, { "list", cmd_list }, { "check_rt", cmd_check_rt },
};

/* Look the command up and run it with the tasks held off. */
int app_dispatch(app_reply_t *reply, int argc, char **argv, int *exit_requested)
{
    int rc;

    if (argc < 1) {
        app_error(reply, "rtapi_app: empty command\n");
        return -1;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        if (strcmp(argv[0], commands[i].name) == 0) {
            rtapi_tasks_lock();
            rc = commands[i].handler(reply, argc, argv, exit_requested);
            rtapi_tasks_unlock();
            return rc;
        }
    }
    app_error(reply, "rtapi_app: unrecognized command starting with %s\n", argv[0]);
    return -1;
}
