/* halcmd_hal.c: halcmd's HAL component (halcmd<pid>), fork id cost and comp name lists. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_hal.h"

/* Register halcmd<pid> with HAL (creates the HAL block when needed). */
int hc_hal_attach(void)
{
    snprintf(hc.progname, sizeof hc.progname, "halcmd%d", (int)getpid());
    hc.comp_id = hal_init(hc.progname);
    if (hc.comp_id < 0) {
        fprintf(stderr, "halcmd: hal_init() failed: %d\n", hc.comp_id);
        return -1;
    }
    hal_ready(hc.comp_id);
    return 0;
}

/* Remove halcmd's component (safe to call twice). */
void hc_hal_detach(void)
{
    if (hc.comp_id > 0)
        hal_exit(hc.comp_id);
    hc.comp_id = 0;
}

/* Spend the ids LinuxCNC's halcmd spends when it forks a child. */
void hc_hal_fork_cost(void)
{
    int id;
    if (hc.comp_id <= 0)
        return;
    id = hal_reattach_for_fork(hc.comp_id);
    if (id > 0)
        hc.comp_id = id;
}

/* -R: force the HAL mutex free. */
int hc_hal_release_mutex(void)
{
    if (hal_lib_init() < 0 || !hal_data) {
        fprintf(stderr, "HALCMD: Release Mutex failed!\n");
        return -1;
    }
    hal_data->mutex.depth = 0;
    hal_data->mutex.owner_pid = 0;
    hal_data->mutex.owner_tid = 0;
    hal_lib_exit();
    return 0;
}

/* Remember the loadrt arguments of a component for save. */
void hc_hal_set_insmod_args(const char *comp, const char *args)
{
    halpr_set_insmod_args(comp, args);
}

/* Names of every component of a type (newest first); caller frees. */
void hc_hal_comp_names(int type, char ***names, int *count)
{
    int n = 0, cap = 0;
    char **v = NULL;
    halpr_mutex_get();
    for (hal_comp_t *c = halpr_first_comp(); c; c = halpr_next_comp(c)) {
        if (c->type != type)
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 16;
            char **nv = realloc(v, cap * sizeof *v);
            if (!nv)
                break;
            v = nv;
        }
        v[n++] = strdup(c->name);
    }
    halpr_mutex_give();
    *names = v;
    *count = n;
}
