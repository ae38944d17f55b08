/* hal_comp_owner.c: is a user component's process still running, and removing the components of dead ones. */
#include "hal_internal.h"
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

/* Start time of a process in clock ticks after boot (field 22 of /proc/PID/stat); 0 when the
   process does not exist or has exited (a zombie nobody reaped). Together with the pid it
   names one process even after pid reuse. */
unsigned long long halpr_process_start(int pid)
{
    char path[64], buf[1024];
    unsigned long long start = 0;
    char state = 'X';
    FILE *f;
    size_t n;
    char *p;

    snprintf(path, sizeof path, "/proc/%d/stat", pid);
    f = fopen(path, "r");
    if (!f)
        return 0;
    n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    p = strrchr(buf, ')');  /* the command name may hold blanks and parentheses */
    if (!p || sscanf(p + 1, " %c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %*u %*u %*d %*d %*d %*d "
                            "%*d %*d %llu", &state, &start) != 2)
        return 0;
    return state == 'Z' || state == 'X' ? 0 : start;
}

/* Non-zero while the process that created a user component still runs (RT comps: always). */
int halpr_comp_owner_alive(const hal_comp_t *comp)
{
    unsigned long long start;

    if (comp->type != HAL_COMP_USER || comp->pid <= 0)
        return 1;
    if (kill(comp->pid, 0) < 0 && errno == ESRCH)
        return 0;
    start = halpr_process_start(comp->pid);
    return start != 0 && (comp->owner_start == 0 || start == comp->owner_start);
}

/* Remove a user component whose process no longer exists, with its pins and params (the
   process was killed and could not call hal_exit). 0 removed, -ENOENT no such component,
   -EINVAL not a user component, -EBUSY its process still runs. */
int hal_comp_remove_orphan(const char *name)
{
    hal_comp_t *comp;
    int rc = 0;

    if (!hal_data || !name)
        return -EINVAL;
    halpr_mutex_get();
    comp = halpr_find_comp_by_name(name);
    if (!comp)
        rc = -ENOENT;
    else if (comp->type != HAL_COMP_USER)
        rc = -EINVAL;
    else if (halpr_comp_owner_alive(comp))
        rc = -EBUSY;
    if (rc == 0) {
        halpr_comp_free_items(comp);
        halpr_index_remove(&hal_data->comps, (hal_node_t *)comp);
        halpr_obj_free(HAL_KIND_COMP, comp);
    }
    halpr_mutex_give();
    return rc;
}
