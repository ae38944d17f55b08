/* halcmd_cmd_funct.c: addf, initf, delf, start, stop, lock, unlock, alias, unalias. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"

/* Signature shared by hal_add_funct_to_thread and hal_init_funct_to_thread. */
typedef int (*hc_funct_adder_t)(const char *funct, const char *thread, int position);

/* Put funct argv[0] into thread argv[1] at position argv[2] (default last). */
static int hc_add_funct(int argc, char *argv[], hc_funct_adder_t add, const char *cmd,
                        const char *where)
{
    int pos = argc > 2 ? atoi(argv[2]) : -1;
    if (add(argv[0], argv[1], pos) < 0) {
        hc_error("%s failed", cmd);
        return -1;
    }
    hc_info("Function '%s' added to %sthread '%s'", argv[0], where, argv[1]);
    return 0;
}

/* addf funct thread [pos] */
int hc_cmd_addf(int argc, char *argv[])
{
    return hc_add_funct(argc, argv, hal_add_funct_to_thread, "addf", "");
}

/* initf funct thread [pos] */
int hc_cmd_initf(int argc, char *argv[])
{
    return hc_add_funct(argc, argv, hal_init_funct_to_thread, "initf", "init of ");
}

/* delf funct [thread] */
int hc_cmd_delf(int argc, char *argv[])
{
    if (hal_del_funct_from_thread(argv[0], argc > 1 ? argv[1] : NULL) < 0) {
        hc_error("delf failed");
        return -1;
    }
    hc_info("Function '%s' removed from thread '%s'", argv[0], argv[1]);
    return 0;
}

/* Start or stop all threads; the library reports a lock itself. */
static int hc_run_threads(int (*action)(void), const char *done)
{
    if (action() < 0)
        return -1;
    hc_info("Realtime threads %s", done);
    return 0;
}

/* start: run all threads. */
int hc_cmd_start(int argc, char *argv[])
{
    (void)argc;
    (void)argv;
    return hc_run_threads(hal_start_threads, "started");
}

/* stop: stop all threads. */
int hc_cmd_stop(int argc, char *argv[])
{
    (void)argc;
    (void)argv;
    return hc_run_threads(hal_stop_threads, "stopped");
}

/* lock [all|tune|none]: set lock bits; unknown words do nothing. */
int hc_cmd_lock(int argc, char *argv[])
{
    const char *w = argc > 0 ? argv[0] : "all";
    if (strcmp(w, "all") == 0)
        return hal_set_lock(HAL_LOCK_ALL) < 0 ? -1 : 0;
    if (strcmp(w, "tune") == 0)
        return hal_set_lock(HAL_LOCK_TUNE) < 0 ? -1 : 0;
    if (strcmp(w, "none") == 0)
        return hal_set_lock(HAL_LOCK_NONE) < 0 ? -1 : 0;
    return 0;
}

/* unlock [all|tune|none]: clear all lock bits, or the tune bits. */
int hc_cmd_unlock(int argc, char *argv[])
{
    const char *w = argc > 0 ? argv[0] : "all";
    if (strcmp(w, "all") == 0 || strcmp(w, "none") == 0)
        return hal_set_lock(HAL_LOCK_NONE) < 0 ? -1 : 0;
    if (strcmp(w, "tune") == 0)
        return hal_set_lock(hal_get_lock() & ~HAL_LOCK_TUNE) < 0 ? -1 : 0;
    return 0;
}

/* Apply an alias (or NULL to remove it) to a pin or param. */
static int hc_set_alias(const char *kind, const char *name, const char *alias)
{
    if (strcmp(kind, "pin") == 0)
        return hal_pin_alias(name, alias);
    if (strcmp(kind, "param") == 0)
        return hal_param_alias(name, alias);
    hc_error("Unknown alias type '%s'", kind);
    return 1;
}

/* alias pin|param name alias */
int hc_cmd_alias(int argc, char *argv[])
{
    int rc = hc_set_alias(argv[0], argv[1], argv[2]);
    (void)argc;
    if (rc < 0)
        hc_error("alias failed");
    return rc != 0 ? -1 : 0;
}

/* unalias pin|param name */
int hc_cmd_unalias(int argc, char *argv[])
{
    int rc = hc_set_alias(argv[0], argv[1], NULL);
    (void)argc;
    if (rc < 0)
        hc_error("unalias failed");
    return rc != 0 ? -1 : 0;
}
