/* halcmd_cmd_funct.c: addf, initf, delf, start, stop, lock, unlock, alias, unalias. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"

/* addf funct thread [pos] */
int hc_cmd_addf(int argc, char *argv[])
{
    int pos = argc > 2 ? atoi(argv[2]) : -1;
    if (hal_add_funct_to_thread(argv[0], argv[1], pos) < 0) {
        hc_error("addf failed");
        return -1;
    }
    hc_info("Function '%s' added to thread '%s'", argv[0], argv[1]);
    return 0;
}

/* initf funct thread [pos] */
int hc_cmd_initf(int argc, char *argv[])
{
    int pos = argc > 2 ? atoi(argv[2]) : -1;
    if (hal_init_funct_to_thread(argv[0], argv[1], pos) < 0) {
        hc_error("initf failed");
        return -1;
    }
    hc_info("Function '%s' added to init of thread '%s'", argv[0], argv[1]);
    return 0;
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

/* start: run all threads (library reports a lock). */
int hc_cmd_start(int argc, char *argv[])
{
    (void)argc;
    (void)argv;
    if (hal_start_threads() < 0)
        return -1;
    hc_info("Realtime threads started");
    return 0;
}

/* stop: stop all threads. */
int hc_cmd_stop(int argc, char *argv[])
{
    (void)argc;
    (void)argv;
    if (hal_stop_threads() < 0)
        return -1;
    hc_info("Realtime threads stopped");
    return 0;
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
