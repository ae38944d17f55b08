/* halcmd_cmd_load.c: loadrt, unloadrt, unload and the realtime side of loading. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <libgen.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "hal.h"
#include "rtapi_client.h"
#include "halcmd.h"
#include "halcmd_cmds.h"
#include "halcmd_hal.h"

/* The bin/ directory beside the lib/ holding librtapi (where rtapi_app lives), for messages. */
const char *hc_bindir(void)
{
    static char dir[PATH_MAX];
    char lib[PATH_MAX];
    Dl_info info;
    if (dir[0])
        return dir;
    if (!dladdr((void *)rtapi_app_command, &info) || !info.dli_fname)
        return ".";
    snprintf(lib, sizeof lib, "%s", info.dli_fname);
    if (snprintf(dir, sizeof dir, "%s/../bin", dirname(lib)) >= (int)sizeof dir)
        snprintf(dir, sizeof dir, ".");
    if (realpath(dir, lib))
        snprintf(dir, sizeof dir, "%s", lib);
    return dir;
}

/* Send a command to the realtime master; prints its reply text. */
static int hc_rtapi(int argc, const char *argv[])
{
    char reply[4096] = "";
    int rc;
    hc_hal_fork_cost();
    rc = rtapi_app_command(argc, argv, 1, reply, sizeof reply);
    if (reply[0]) {
        size_t n = strlen(reply);
        fprintf(rc < 0 ? hc_stderr() : hc_stdout(), "%s%s", reply,
                reply[n - 1] == '\n' ? "" : "\n");
    }
    return rc;
}

/* Report a failed insmod of mod. */
static int hc_loadrt_failed(const char *mod, int child_failed)
{
    if (child_failed)
        hc_error("waitpid failed %s/rtapi_app %s", hc_bindir(), mod);
    hc_error("%s/rtapi_app exited without becoming ready", hc_bindir());
    hc_error("insmod for %s failed, returned -1", mod);
    return -1;
}

/* Join argv[from..argc) with single blanks into buf. */
static void hc_join_args(int argc, char *argv[], int from, char *buf, size_t size)
{
    size_t len = 0;
    buf[0] = '\0';
    for (int i = from; i < argc && len < size; i++)
        len += snprintf(buf + len, size - len, "%s%s", i > from ? " " : "", argv[i]);
}

/* loadrt mod [args]: load a realtime module and wait for its component. */
int hc_cmd_loadrt(int argc, char *argv[])
{
    const char *args[HC_MAX_TOKENS + 2];
    char joined[HC_LINE_MAX];
    hal_comp_info_t info;
    int n = 0;
    if (hal_get_lock() & HAL_LOCK_LOAD) {
        hc_error("HAL is locked, loading of programs is not permitted");
        hc_error("insmod for %s failed, returned -1", argv[0]);
        return -1;
    }
    args[n++] = "load";
    for (int i = 0; i < argc && n < HC_MAX_TOKENS + 1; i++)
        args[n++] = argv[i];
    if (hc_rtapi(n, args) != 0)
        return hc_loadrt_failed(argv[0], 1);
    if (hal_comp_by_name(argv[0], &info) < 0 || !info.ready)
        return hc_loadrt_failed(argv[0], 0);
    hc_join_args(argc, argv, 1, joined, sizeof joined);
    hc_hal_set_insmod_args(argv[0], joined);
    hc_info("Realtime module '%s' loaded", argv[0]);
    return 0;
}

/* Unload one realtime component through the master. */
static int hc_unloadrt_one(const char *name)
{
    const char *args[] = {"unload", name};
    int rc = hc_rtapi(2, args);
    if (rc != 0) {
        hc_error("exit value: %d", rc & 255);
        hc_error("rmmod failed, returned -1");
        hc_error("unloadrt failed on '%s'", name);
        return -1;
    }
    hc_info("Realtime module '%s' unloaded", name);
    return 0;
}

/* Unload every RT component (except __ pseudo comps), newest first. */
static int hc_unloadrt_all(void)
{
    char **names = NULL;
    int count = 0, rc = 0;
    hc_hal_comp_names(HC_COMP_TYPE_RT, &names, &count);
    for (int i = 0; i < count; i++) {
        if (strncmp(names[i], "__", 2) != 0 && hc_unloadrt_one(names[i]) < 0)
            rc = -1;
        free(names[i]);
    }
    free(names);
    return rc;
}

/* Look up a loaded component; logs and returns -1 when there is none of that name. */
static int hc_loaded_comp(const char *name, hal_comp_info_t *info)
{
    if (hal_comp_by_name(name, info) < 0) {
        hc_error("component '%s' is not loaded", name);
        return -1;
    }
    return 0;
}

/* unloadrt name|all */
int hc_cmd_unloadrt(int argc, char *argv[])
{
    hal_comp_info_t info;
    (void)argc;
    if (strcmp(argv[0], "all") == 0)
        return hc_unloadrt_all();
    if (hc_loaded_comp(argv[0], &info) < 0)
        return -1;
    if (info.type != HC_COMP_TYPE_RT) {
        hc_error("component '%s' is not a realtime module", argv[0]);
        return -1;
    }
    return hc_unloadrt_one(argv[0]);
}

/* unload name|all: user comps get SIGTERM, RT comps are unloaded. */
int hc_cmd_unload(int argc, char *argv[])
{
    hal_comp_info_t info;
    if (strcmp(argv[0], "all") == 0) {
        hc_cmd_unloadusr(argc, argv);
        return hc_unloadrt_all();
    }
    if (hc_loaded_comp(argv[0], &info) < 0)
        return -1;
    if (info.type == HC_COMP_TYPE_RT)
        return hc_unloadrt_one(argv[0]);
    return hc_cmd_unloadusr(argc, argv);
}
