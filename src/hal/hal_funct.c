/* hal_funct.c: exporting realtime functions with their .time/.tmax/.tmax-increased items (hal.md §8). */
#include "hal_internal.h"
#include <stdarg.h>

/* Checks before exporting: init, lock, name length, RT, not ready, unique; mutex held. */
static int hal_export_check(const char *name, int comp_id, hal_comp_t **out)
{
    hal_comp_t *comp;
    int rc;

    rc = halpr_name_check("function", name, HAL_NAME_LEN - strlen(".tmax-increased"));
    if (rc < 0)
        return rc;
    rc = halpr_comp_check(comp_id, "export_funct", &comp);
    if (rc < 0)
        return rc;
    if (comp->type != HAL_COMP_RT) {
        HAL_ERR("component %d is not realtime\n", comp_id);
        return -EINVAL;
    }
    if (halpr_find_funct_by_name(name)) {
        HAL_ERR("duplicate function '%s'\n", name);
        return -EINVAL;
    }
    *out = comp;
    return 0;
}

/* Create <name>.time, .tmax, .tmax-increased with their cells in one timing block. */
static int hal_funct_items(hal_funct_t *f, int comp_id)
{
    hal_funct_timing_t *tm = hal_malloc(sizeof *tm);
    int rc;

    if (!tm)
        return -ENOMEM;
    rc = hal_pin_s32_newf(HAL_OUT, &tm->time, comp_id, "%s.time", f->name);
    if (rc == 0)
        rc = hal_param_s32_newf(HAL_RW, &tm->tmax, comp_id, "%s.tmax", f->name);
    if (rc == 0)
        rc = hal_param_bit_newf(HAL_RO, &tm->tmax_increased, comp_id, "%s.tmax-increased",
                                f->name);
    f->timing = tm;
    return rc;
}

/* Export a realtime function of an RT component. */
int hal_export_funct(const char *name, void (*funct)(void *, long), void *arg,
                     int uses_fp, int reentrant, int comp_id)
{
    hal_comp_t *comp;
    hal_funct_t *f;
    int rc;

    if (!hal_data) {
        HAL_ERR("export_funct called before init\n");
        return -EINVAL;
    }
    if (!name || !funct) {
        HAL_ERR("export_funct called without a name or function\n");
        return -EINVAL;
    }
    if (hal_data->lock & HAL_LOCK_LOAD) {
        HAL_ERR("export_funct called while HAL locked\n");
        return -EPERM;
    }
    halpr_mutex_get();
    rc = hal_export_check(name, comp_id, &comp);
    f = rc == 0 ? halpr_obj_alloc(HAL_KIND_FUNCT) : NULL;
    if (rc == 0 && !f)
        rc = -ENOMEM;
    if (rc == 0) {
        strcpy(f->name, name);
        f->uses_fp = uses_fp;
        f->reentrant = reentrant;
        f->owner_ptr = SHMOFF(comp);
        f->arg = arg;
        f->funct = funct;
        halpr_index_insert_sorted(&hal_data->functs, (hal_node_t *)f);
        rc = hal_funct_items(f, comp_id);
        if (rc < 0)
            halpr_funct_free(f);
    }
    halpr_mutex_give();
    return rc;
}

/* printf-style variant of hal_export_funct. */
int hal_export_functf(void (*funct)(void *, long), void *arg, int uses_fp,
                      int reentrant, int comp_id, const char *fmt, ...)
{
    char name[HAL_NAME_LEN + 1];
    va_list ap;
    int rc;

    va_start(ap, fmt);
    rc = halpr_name_fmt(name, fmt, ap);
    va_end(ap);
    if (rc < 0)
        return rc;
    return hal_export_funct(name, funct, arg, uses_fp, reentrant, comp_id);
}

/* Remove a funct from every thread and free it; mutex held. */
void halpr_funct_free(hal_funct_t *funct)
{
    halpr_thread_drop_funct(funct);
    halpr_index_remove(&hal_data->functs, (hal_node_t *)funct);
    halpr_obj_free(HAL_KIND_FUNCT, funct);
}
