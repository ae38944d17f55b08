/* sampling_cli.h: command line and HAL set-up shared by halsampler and halstreamer. */
#ifndef SAMPLING_CLI_H
#define SAMPLING_CLI_H

#include <signal.h>
#include "hal.h"

#define SAMPLING_MAX_CHANNELS 8
#define SAMPLING_MAX_FIELDS 21
#define SAMPLER_KEY_BASE 0x48534130
#define STREAMER_KEY_BASE 0x48535430

/* Parsed command line of halsampler/halstreamer. */
typedef struct {
    int channel;
    long count;           /* -n; -1 = forever */
    int tag;              /* -t */
    const char *comp_name; /* -N; NULL = default */
    const char *filename;
} sampling_opts_t;

/* Set by SIGINT/SIGTERM. */
extern volatile sig_atomic_t sampling_stop;

/* Parses argv; `allowed` lists the option letters accepted. 0, -1 (message printed) or 1 when
   --help/-h printed usage_text on stdout. */
int sampling_parse_args(int argc, char **argv, const char *allowed, const char *usage_text,
                        sampling_opts_t *opts);

/* Installs SIGINT/SIGTERM handlers that set sampling_stop (no restart). */
void sampling_install_signals(void);

/* Creates component `<base><chan>` (or -N) and attaches the stream; comp id or -1. */
int sampling_attach(const sampling_opts_t *opts, const char *base, int key_base,
                    hal_stream_t *stream);

/* Sleeps a short while between FIFO polls. */
void sampling_poll_sleep(void);

#endif
