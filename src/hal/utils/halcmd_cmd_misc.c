/* halcmd_cmd_misc.c: echo, unecho, print, source, setexact, debug and status. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "hal.h"
#include "rtapi_client.h"
#include "halcmd.h"
#include "halcmd_cmds.h"
#include "halcmd_hal.h"

/* Switch echoing of input lines on or off and say so. */
static int hc_set_echo(int on)
{
    hc_print("Echo %s\n", on ? "on" : "off");
    hc.echo = on;
    return 0;
}

/* echo: turn on echoing of input lines. */
int hc_cmd_echo(int argc, char *argv[])
{
    (void)argc;
    (void)argv;
    return hc_set_echo(1);
}

/* unecho: turn echoing off. */
int hc_cmd_unecho(int argc, char *argv[])
{
    (void)argc;
    (void)argv;
    return hc_set_echo(0);
}

/* print [msg]: message on stderr with the file:line: prefix. */
int hc_cmd_print(int argc, char *argv[])
{
    hc_error("HALCMD MSG: %s", argc > 0 ? argv[0] : "(null)");
    return 0;
}

#define HC_MAX_SOURCE_DEPTH 16

/* source file: run another HAL file, stopping at its first failing line. */
int hc_cmd_source(int argc, char *argv[])
{
    static int depth;
    char name[HC_LINE_MAX], lib_path[HC_LINE_MAX];
    const char *saved_file = hc.file;
    int saved_line = hc.line, saved_keep = hc.keep_going, rc;
    FILE *f;
    (void)argc;
    snprintf(name, sizeof name, "%s", hc_resolve_lib(argv[0], lib_path, sizeof lib_path));
    if (depth >= HC_MAX_SOURCE_DEPTH) {
        hc_error("source: files nested more than %d deep", HC_MAX_SOURCE_DEPTH);
        return -1;
    }
    f = hc_open_hal_file(name);
    if (!f) {
        hc_error("Could not open hal file '%s': %s", name, strerror(errno));
        return -1;
    }
    hc.file = name;
    hc.line = 0;
    hc.keep_going = 0;
    depth++;
    rc = hc_run_stream(f, 0, 0);
    depth--;
    fclose(f);
    hc.file = saved_file;
    hc.line = saved_line;
    hc.keep_going = saved_keep;
    return rc;
}

/* setexact_for_test_suite_only: use the next requested base period verbatim. */
int hc_cmd_setexact(int argc, char *argv[])
{
    (void)argc;
    (void)argv;
    if (hal_set_exact_period() < 0) {
        hc_error("HAL_LIB: Cannot run 'setexact' after a thread has been created");
        return -1;
    }
    hc_warning("HAL_LIB: HAL will pretend that the exact base period requested is possible.\n"
               "This mode is not suitable for running real hardware.");
    return 0;
}

/* debug level: set the realtime side's message level. */
int hc_cmd_debug(int argc, char *argv[])
{
    const char *args[] = {"debug", argv[0]};
    char reply[1024] = "";
    int rc;
    (void)argc;
    hc_hal_fork_cost();
    rc = rtapi_app_command(2, args, 1, reply, sizeof reply);
    if (reply[0])
        fprintf(rc < 0 ? hc_stderr() : hc_stdout(), "%s%s", reply,
                reply[strlen(reply) - 1] == '\n' ? "" : "\n");
    if (rc != 0) {
        hc_error("exit value: %d", rc & 255);
        return -1;
    }
    return 0;
}

/* Print the lock part of status. */
static void hc_status_lock(void)
{
    unsigned lock = hal_get_lock();
    hc_out("HAL locking status:\n  current lock value %u (%02x)\n", lock, lock);
    if (lock == HAL_LOCK_NONE)
        hc_out("  HAL_LOCK_NONE - nothing is locked\n");
    if (lock & HAL_LOCK_LOAD)
        hc_out("  HAL_LOCK_LOAD    - loading of new components is locked\n");
    if (lock & HAL_LOCK_CONFIG)
        hc_out("  HAL_LOCK_CONFIG  - link and addf is locked\n");
    if (lock & HAL_LOCK_PARAMS)
        hc_out("  HAL_LOCK_PARAMS  - setting params is locked\n");
    if (lock & HAL_LOCK_RUN)
        hc_out("  HAL_LOCK_RUN     - running/stopping HAL is locked\n");
}

/* Print one "label:  active/recycled" line with values in column 31. */
static void hc_status_line(const char *what, long a, long b)
{
    char label[64];
    snprintf(label, sizeof label, "  active/recycled %s:", what);
    hc_out("%-30s%ld/%ld\n", label, a, b);
}

/* Print the memory part of status. */
static void hc_status_mem(void)
{
    hal_stats_t s;
    memset(&s, 0, sizeof s);
    hal_statistics(&s);
    hc_out("HAL memory status\n");
    hc_out("%-30s%ld/%ld\n", "  used/total shared memory:", s.mem_used, s.mem_total);
    hc_status_line("components", s.comps_active, s.comps_recycled);
    hc_status_line("pins", s.pins_active, s.pins_recycled);
    hc_status_line("parameters", s.params_active, s.params_recycled);
    hc_status_line("aliases", s.aliases_active, s.aliases_recycled);
    hc_status_line("signals", s.sigs_active, s.sigs_recycled);
    hc_status_line("functions", s.functs_active, s.functs_recycled);
    hc_status_line("threads", s.threads_active, s.threads_recycled);
}

/* status [lock|mem|all] */
int hc_cmd_status(int argc, char *argv[])
{
    const char *w = argc > 0 ? argv[0] : "all";
    if (strcmp(w, "lock") == 0) {
        hc_status_lock();
    } else if (strcmp(w, "mem") == 0) {
        hc_status_mem();
    } else if (strcmp(w, "all") == 0) {
        hc_status_lock();
        hc_status_mem();
    } else {
        hc_error("Unknown 'status' type '%s'", w);
        return -1;
    }
    return 0;
}
