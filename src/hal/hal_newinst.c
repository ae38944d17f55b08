/* hal_newinst.c: `rtapi_app newinst`: run a component's registered constructor in rtapi_app. */
#include <stdio.h>
#include "hal_internal.h"

/* Join argv with single spaces into buf (the constructor's one argument string). */
static int join_args(char *buf, size_t size, int argc, const char **argv)
{
    size_t len = 0;

    buf[0] = '\0';
    for (int i = 0; i < argc; i++) {
        int n = snprintf(buf + len, size - len, "%s%s", i ? " " : "", argv[i]);
        if (n < 0 || (size_t)n >= size - len)
            return -ENOMEM;
        len += (size_t)n;
    }
    return 0;
}

/* Look up comp_name, its ready flag and its constructor; -ENOENT / -ENOEXEC with a message. */
static int find_constructor(const char *comp_name, int *comp_id, int *ready,
                            hal_constructor_t *make)
{
    hal_comp_t *comp;
    int rc = 0;

    halpr_mutex_get();
    comp = halpr_find_comp_by_name(comp_name);
    if (!comp) {
        HAL_ERR("newinst: component '%s' not found\n", comp_name);
        rc = -ENOENT;
    } else if (comp->type != HAL_COMP_RT || !comp->make) {
        HAL_ERR("newinst: component '%s': %s\n", comp_name, hal_strerror(-ENOEXEC));
        rc = -ENOEXEC;
    } else {
        *comp_id = comp->comp_id;
        *ready = comp->ready;
        *make = comp->make;
    }
    halpr_mutex_give();
    return rc;
}

/* Create instance `inst_name` of component comp_name with its constructor (RT process
   only); the component is made unready while the constructor adds items. */
int hal_newinst(const char *comp_name, const char *inst_name, int argc, const char **argv)
{
    char name[HAL_NAME_LEN + 1], arg[1024];
    hal_constructor_t make = NULL;
    int comp_id = 0, ready = 0, rc;

    if (!hal_data || !hal_proc_is_rt) {
        HAL_ERR("newinst: only possible inside the realtime process\n");
        return -EINVAL;
    }
    if (!comp_name || !inst_name || !*inst_name || strlen(inst_name) > HAL_NAME_LEN) {
        HAL_ERR("newinst: instance name '%s' is empty or too long\n", inst_name ? inst_name : "");
        return -EINVAL;
    }
    if (join_args(arg, sizeof arg, argc, argv) < 0) {
        HAL_ERR("newinst: arguments for '%s' are too long\n", inst_name);
        return -EINVAL;
    }
    rc = find_constructor(comp_name, &comp_id, &ready, &make);
    if (rc < 0)
        return rc;
    strcpy(name, inst_name);
    hal_set_unready(comp_id);
    rc = make(name, arg);
    if (ready)
        hal_ready(comp_id);
    if (rc < 0)
        HAL_ERR("newinst: constructor of '%s' failed for '%s': %s\n", comp_name, inst_name,
                hal_strerror(rc));
    return rc;
}
