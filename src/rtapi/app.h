/* app.h: pieces of rtapi_app shared between its source files. */
#ifndef RTAPI_APP_PRIV_H
#define RTAPI_APP_PRIV_H

#include <stddef.h>
#include "rtapi_wire.h"

/* Reply being built for the current client. */
typedef struct {
    char text[RTAPI_WIRE_MAX - 16];
    size_t len;
    int peer_shares_stderr;   /* client's stderr is ours: do not repeat errors */
} app_reply_t;

/* Append informational text for the client's stdout. */
void app_say(app_reply_t *reply, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Report an error line: master's stderr, and the reply unless the client shares it. */
void app_error(app_reply_t *reply, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Load a module: argv[0] is the name, the rest name=value arguments. */
int app_load(app_reply_t *reply, int argc, char **argv);
/* Call rtapi_app_exit and dlclose; refuses hal_lib. */
int app_unload(app_reply_t *reply, const char *name);
/* Module names, one per line, in load order. */
void app_list(app_reply_t *reply);
/* Unload every module, newest first, hal_lib last. */
void app_unload_all(void);
/* dlopen liblinuxcnchal (when built) globally so modules resolve hal_* from it. */
void app_preload_hal_library(void);

/* Run one decoded command; sets *exit_requested for `exit`. */
int app_dispatch(app_reply_t *reply, int argc, char **argv, int *exit_requested);
/* Serve commands on the listening socket until `exit`; returns the exit status. */
int app_master_run(int listen_fd);

#endif
