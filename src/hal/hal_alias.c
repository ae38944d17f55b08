/* hal_alias.c: pin and param aliases (spec/hal.md §11): rename, remember the original. */
#include "hal_internal.h"
#include <stdio.h>

/* Where a pin/param keeps its name and alias record; pins also re-sort in their signal. */
typedef struct {
    hal_index_t *index;     /* pins or params */
    int *alias_list;        /* pin_alias_list or param_alias_list */
    int *oldname;           /* the object's oldname field */
    hal_node_t *node;       /* the object */
    hal_pin_t *pin;         /* the pin (NULL for params) */
} hal_alias_target_t;

/* Rename the object and re-sort it in its lists. */
static void hal_alias_rename(hal_alias_target_t *t, const char *name)
{
    hal_sig_t *sig = (t->pin && t->pin->signal) ? SHMPTR(t->pin->signal) : NULL;

    halpr_index_remove(t->index, t->node);
    if (sig)
        halpr_sig_pin_remove(sig, t->pin);
    strcpy(t->node->name, name);
    halpr_index_insert_sorted(t->index, t->node);
    if (sig)
        halpr_sig_pin_insert(sig, t->pin);
}

/* Drop the alias record and go back to the original name (no-op when none). */
static void hal_alias_restore(hal_alias_target_t *t)
{
    hal_oldname_t *o;
    int *link = t->alias_list;

    if (!*t->oldname)
        return;
    o = SHMPTR(*t->oldname);
    while (*link && *link != *t->oldname)
        link = &((hal_oldname_t *)SHMPTR(*link))->next_ptr;
    if (*link)
        *link = o->next_ptr;
    *t->oldname = 0;
    hal_alias_rename(t, o->name);
    halpr_obj_free(HAL_KIND_ALIAS, o);
}

/* Give the object a new name, creating the alias record on first use. */
static int hal_alias_set(hal_alias_target_t *t, const char *alias)
{
    if (!*t->oldname) {
        hal_oldname_t *o = halpr_obj_alloc(HAL_KIND_ALIAS);
        if (!o)
            return -ENOMEM;
        strcpy(o->name, t->node->name);
        o->obj_ptr = SHMOFF(t->node);
        o->next_ptr = *t->alias_list;
        *t->alias_list = SHMOFF(o);
        *t->oldname = SHMOFF(o);
    }
    hal_alias_rename(t, alias);
    return 0;
}

/* Checks shared by pin and param aliasing. */
static int hal_alias_precheck(const char *what, const char *name, const char *alias)
{
    char func[16];
    int rc;

    snprintf(func, sizeof func, "%s_alias", what);
    rc = halpr_check_unlocked(func, HAL_LOCK_CONFIG, "%s called while HAL locked");
    if (rc < 0)
        return rc;
    if (!name) {
        HAL_ERR("%s_alias called without a name\n", what);
        return -EINVAL;
    }
    return alias ? halpr_name_check("alias", alias, HAL_NAME_LEN) : 0;
}

/* Finds a pin (is_pin) or param by name or alias, as a list node. */
static hal_node_t *hal_alias_find(int is_pin, const char *name)
{
    if (is_pin)
        return (hal_node_t *)halpr_find_pin_by_name(name);
    return (hal_node_t *)halpr_find_param_by_name(name);
}

/* Describes where a pin (is_pin) or param node keeps its name and alias record. */
static void hal_alias_target_init(hal_alias_target_t *t, int is_pin, hal_node_t *node)
{
    if (is_pin) {
        hal_pin_t *pin = (hal_pin_t *)node;
        *t = (hal_alias_target_t){&hal_data->pins, &hal_data->pin_alias_list,
                                  &pin->oldname, node, pin};
    } else {
        hal_param_t *param = (hal_param_t *)node;
        *t = (hal_alias_target_t){&hal_data->params, &hal_data->param_alias_list,
                                  &param->oldname, node, NULL};
    }
}

/* Alias (or with NULL un-alias) a pin (is_pin) or param under the HAL mutex. */
static int hal_alias_apply(int is_pin, const char *name, const char *alias)
{
    const char *what = is_pin ? "pin" : "param";
    hal_alias_target_t t;
    hal_node_t *node, *other;
    int rc = hal_alias_precheck(what, name, alias);

    if (rc < 0)
        return rc;
    halpr_mutex_get();
    other = alias ? hal_alias_find(is_pin, alias) : NULL;
    node = hal_alias_find(is_pin, name);
    if (!node) {
        HAL_ERR("%s '%s' not found\n", what, name);
        rc = -EINVAL;
    } else if (other && other != node) {
        HAL_ERR("duplicate %s/alias name '%s'\n", is_pin ? "pin" : "parameter", alias);
        rc = -EINVAL;
    } else {
        hal_alias_target_init(&t, is_pin, node);
        if (!alias)
            hal_alias_restore(&t);
        else
            rc = hal_alias_set(&t, alias);
    }
    halpr_mutex_give();
    return rc;
}

/* Alias (or with NULL un-alias) a pin. */
int hal_pin_alias(const char *pin_name, const char *alias)
{
    return hal_alias_apply(1, pin_name, alias);
}

/* Alias (or with NULL un-alias) a param. */
int hal_param_alias(const char *param_name, const char *alias)
{
    return hal_alias_apply(0, param_name, alias);
}
