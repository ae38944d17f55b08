/* sampling_cli.c: option parsing, signals and stream attach for halsampler/halstreamer. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "rtapi.h"
#include "hal.h"
#include "sampling_cli.h"

volatile sig_atomic_t sampling_stop;

/* Parses a whole-string decimal integer; -1 when malformed or negative. */
static long parse_count(const char *text)
{
    char *end;
    long value;

    if (text[0] == '\0') {
        return -1;
    }
    errno = 0;
    value = strtol(text, &end, 10);
    if (*end != '\0' || errno != 0 || value < 0) {
        return -1;
    }
    return value;
}

/* Applies option letter `opt` with value `val`; 0 or -1 after printing an error. */
static int apply_option(char opt, const char *val, sampling_opts_t *opts)
{
    long v;
    switch (opt) {
    case 'c':
        v = parse_count(val);
        if (v < 0 || v >= SAMPLING_MAX_CHANNELS) {
            fprintf(stderr, "ERROR: invalid channel number '%s'\n", val);
            return -1;
        }
        opts->channel = (int)v;
        return 0;
    case 'n':
        v = parse_count(val);
        if (v < 0) {
            fprintf(stderr, "ERROR: invalid sample count '%s'\n", val);
            return -1;
        }
        opts->count = v;
        return 0;
    case 'N':
        if (val[0] == '\0' || strlen(val) > HAL_NAME_LEN) {
            fprintf(stderr, "ERROR: invalid component name '%s'\n", val);
            return -1;
        }
        opts->comp_name = val;
        return 0;
    default:
        return -1;
    }
}

/* Handles one `-X[value]` argument at argv[*i]; 0 or -1 after an error. */
static int parse_option(int argc, char **argv, int *i, const char *allowed,
                        sampling_opts_t *opts)
{
    const char *arg = argv[*i];
    char opt = arg[1];

    if (opt == '\0' || strchr(allowed, opt) == NULL) {
        fprintf(stderr, "ERROR: unknown option '%.1s'\n", arg + 1);
        return -1;
    }
    if (opt == 't') {
        opts->tag = 1;
        return 0;
    }
    if (arg[2] != '\0') {
        return apply_option(opt, arg + 2, opts);
    }
    if (*i + 1 >= argc) {
        fprintf(stderr, "ERROR: option '-%c' needs a value\n", opt);
        return -1;
    }
    (*i)++;
    return apply_option(opt, argv[*i], opts);
}

/* Parses the whole command line into opts; 1 after printing the help text. */
int sampling_parse_args(int argc, char **argv, const char *allowed, const char *usage_text,
                        sampling_opts_t *opts)
{
    int i;

    memset(opts, 0, sizeof(*opts));
    opts->count = -1;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(usage_text, stdout);
            return 1;
        }
        if (argv[i][0] == '-') {
            if (parse_option(argc, argv, &i, allowed, opts) < 0) {
                return -1;
            }
        } else if (opts->filename != NULL) {
            fprintf(stderr, "ERROR: At most one filename may be specified\n");
            return -1;
        } else {
            opts->filename = argv[i];
        }
    }
    return 0;
}

/* Signal handler: asks the main loop to finish. */
static void on_signal(int sig)
{
    (void)sig;
    sampling_stop = 1;
}

/* Installs the SIGINT/SIGTERM handlers without SA_RESTART so blocking reads return. */
void sampling_install_signals(void)
{
    struct sigaction sa;

    memset(&sa, 0, sizeof(sa));
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

/* Registers the user component and attaches to the channel's stream. */
int sampling_attach(const sampling_opts_t *opts, const char *base, int key_base,
                    hal_stream_t *stream)
{
    char name[HAL_NAME_LEN + 1];
    int comp_id, retval;

    if (opts->comp_name != NULL) {
        snprintf(name, sizeof(name), "%s", opts->comp_name);
    } else {
        snprintf(name, sizeof(name), "%s%d", base, opts->channel);
    }
    comp_id = hal_init(name);
    if (comp_id < 0) {
        fprintf(stderr, "%s: ERROR: hal_init() failed: %s\n", name, strerror(-comp_id));
        return -1;
    }
    retval = hal_stream_attach(stream, comp_id, key_base + opts->channel, NULL);
    if (retval == -ENOENT) {
        retval = -EINVAL;  /* LinuxCNC reports a missing stream as an invalid argument */
    }
    if (retval < 0) {
        fprintf(stderr, "hal_stream_attach: %s\n", strerror(-retval));
        hal_exit(comp_id);
        return -1;
    }
    hal_ready(comp_id);
    return comp_id;
}

/* Waits 1 ms; interrupted early by signals. */
void sampling_poll_sleep(void)
{
    struct timespec ts = { 0, 1000000 };
    nanosleep(&ts, NULL);
}
