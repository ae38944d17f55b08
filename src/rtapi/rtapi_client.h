/* rtapi_client.h: talk to this instance's rtapi_app master over its UNIX socket. */
#ifndef RTAPI_CLIENT_H
#define RTAPI_CLIENT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Send argv (e.g. {"load","siggen","num_chan=2"}) to the master and return its
   integer result (0 or negative errno style; -1 for generic failure). The
   master's reply text (possibly empty) is copied NUL-terminated to reply:
   callers print it on stdout when the result is >= 0, on stderr otherwise.
   autostart != 0 starts a master (running `rtapi_app start`) when none
   answers, after printing the "Deprecated" warning on stderr. Without a
   master and without autostart the result is -ENOTCONN. */
int rtapi_app_command(int argc, const char *const argv[], int autostart,
                      char *reply, size_t reply_size);

/* Process id of this instance's master (from the socket peer), or -1. */
int rtapi_app_master_pid(void);

/* 1 when this instance's master answers a ping, else 0. */
int rtapi_app_running(void);

#ifdef __cplusplus
}
#endif

#endif
