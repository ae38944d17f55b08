/* halcmd_main.c: halcmd entry point: options, HAL attach, argv or file mode, exit status. */
#include <errno.h>
#include <getopt.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "hal.h"
#include "rtapi.h"
#include "halcmd.h"
#include "halcmd_hal.h"

/* Options collected by getopt before anything runs. */
typedef struct {
    int file_mode, release, complete, help, msg_level;
} hc_opts_t;

/* Leave HAL cleanly on SIGINT/SIGTERM and exit with status 1. */
static void hc_on_signal(int sig)
{
    (void)sig;
    hc_hal_detach();
    _exit(1);
}

/* Parse the options; returns -1 on an unknown option. */
static int hc_parse_options(int argc, char *argv[], hc_opts_t *o)
{
    static const struct option longopts[] = {{"help", no_argument, NULL, 'h'}, {NULL, 0, NULL, 0}};
    int c;
    o->msg_level = RTAPI_MSG_ERR;
    while ((c = getopt_long(argc, argv, "+RCfi:kqQsvVhe", longopts, NULL)) != -1) {
        switch (c) {
        case 'R': o->release = 1; break;
        case 'C': o->complete = 1; break;
        case 'f': o->file_mode = 1; break;
        case 'i': if (!hc.ini_file) hc.ini_file = optarg; break;
        case 'k': hc.keep_going = 1; break;
        case 'q': o->msg_level = RTAPI_MSG_ERR; break;
        case 'Q': o->msg_level = RTAPI_MSG_NONE; hc.quiet = 1; break;
        case 's': hc.script_mode = 1; break;
        case 'v': o->msg_level = RTAPI_MSG_INFO; hc.verbose = 1; break;
        case 'V': o->msg_level = RTAPI_MSG_ALL; hc.verbose = 1; break;
        case 'h': o->help = 1; break;
        case 'e': hc.echo = 1; break;
        default: return -1;
        }
    }
    return 0;
}

/* Run the command given on the command line (argv mode). */
static int hc_run_argv(int argc, char *argv[])
{
    int n = 0;
    while (n < argc && argv[n][0] != '\0')
        n++;
    hc.argv_mode = 1;
    hc.file = "<commandline>";
    hc.line = 0;
    return hc_run_tokens(n, argv) < 0 ? -1 : 0;
}

/* Run commands from a file (or stdin when name is NULL). */
static int hc_run_file(const char *name)
{
    char lib_path[4096];
    FILE *f = stdin;
    int rc;
    if (name)
        name = hc_resolve_lib(name, lib_path, sizeof lib_path);
    if (name) {
        f = hc_open_hal_file(name);
        if (!f) {
            fprintf(stderr, "Could not open command file '%s': %s\n", name, strerror(errno));
            return -2;
        }
    }
    hc.file = name ? name : "<stdin>";
    hc.line = 0;
    if (!name && isatty(0) && !hc.script_mode)
        rc = hc_run_interactive();
    else
        rc = hc_run_stream(f, 1, isatty(fileno(f)));
    if (name)
        fclose(f);
    return rc;
}

/* Dispatch to release, help, completion, argv or file mode. */
static int hc_dispatch(int argc, char *argv[], hc_opts_t *o)
{
    if (o->help) {
        if (optind < argc)
            hc_help_command(argv[optind]);
        else
            hc_usage();
        return 0;
    }
    if (o->complete)
        return hc_complete_bash();
    if (o->release)
        return hc_hal_release_mutex();
    if (hc.ini_file && !o->file_mode) {
        fprintf(stderr, "-i may only be used together with -f\n");
        return -1;
    }
    if (!o->file_mode && optind >= argc) {
        hc_usage();
        return 0;
    }
    if (hc_hal_attach() < 0)
        return -1;
    return o->file_mode ? hc_run_file(optind < argc ? argv[optind] : NULL)
                        : hc_run_argv(argc - optind, argv + optind);
}

/* halcmd main: exit 0 when no command failed, 1 otherwise, 255 on usage errors. */
int main(int argc, char *argv[])
{
    hc_opts_t opts = {0};
    int rc;
    if (argc < 2) {
        hc_usage();
        return 0;
    }
    if (hc_parse_options(argc, argv, &opts) < 0)
        return 255;
    rtapi_set_msg_level(opts.msg_level);
    signal(SIGINT, hc_on_signal);
    signal(SIGTERM, hc_on_signal);
    rc = hc_dispatch(argc, argv, &opts);
    hc_hal_detach();
    if (rc == -2)
        return 255;
    return rc < 0 ? 1 : 0;
}
