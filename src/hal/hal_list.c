/* hal_list.c: name lookup (halpr_find_*), list walks for tools, component info and statistics. */
#include "hal_internal.h"
#include <stddef.h>

/* Component by name, or NULL. */
hal_comp_t *halpr_find_comp_by_name(const char *name)
{
    return (hal_comp_t *)halpr_index_find(&hal_data->comps, name);
}

/* Component by rtapi id, or NULL. */
hal_comp_t *halpr_find_comp_by_id(int id)
{
    hal_comp_t *c;
    for (c = halpr_first_comp(); c; c = halpr_next_comp(c))
        if (c->comp_id == id)
            return c;
    return NULL;
}

/* Object whose ORIGINAL name (before aliasing) is `name`, from an alias list. */
static void *hal_find_by_oldname(int list, const char *name)
{
    while (list && name) {
        hal_oldname_t *o = SHMPTR(list);
        if (strcmp(o->name, name) == 0)
            return SHMPTR(o->obj_ptr);
        list = o->next_ptr;
    }
    return NULL;
}

/* Pin by current or original name, or NULL. */
hal_pin_t *halpr_find_pin_by_name(const char *name)
{
    hal_pin_t *p = (hal_pin_t *)halpr_index_find(&hal_data->pins, name);
    return p ? p : hal_find_by_oldname(hal_data->pin_alias_list, name);
}

/* Param by current or original name, or NULL. */
hal_param_t *halpr_find_param_by_name(const char *name)
{
    hal_param_t *p = (hal_param_t *)halpr_index_find(&hal_data->params, name);
    return p ? p : hal_find_by_oldname(hal_data->param_alias_list, name);
}

/* Signal by name, or NULL. */
hal_sig_t *halpr_find_sig_by_name(const char *name)
{
    return (hal_sig_t *)halpr_index_find(&hal_data->sigs, name);
}

/* Function by name, or NULL. */
hal_funct_t *halpr_find_funct_by_name(const char *name)
{
    return (hal_funct_t *)halpr_index_find(&hal_data->functs, name);
}

/* Thread by name, or NULL. */
hal_thread_t *halpr_find_thread_by_name(const char *name)
{
    return (hal_thread_t *)halpr_index_find(&hal_data->threads, name);
}

/* Next node of idx after start (NULL = first) whose int at owner_off is owner's offset. */
static hal_node_t *halpr_find_node_by_owner(const hal_index_t *idx, size_t owner_off,
                                            hal_comp_t *owner, hal_node_t *start)
{
    int want = SHMOFF(owner);
    hal_node_t *n = HALPR_AT(hal_node_t, start ? start->next_ptr : idx->list_ptr);

    while (n && *(const int *)((const char *)n + owner_off) != want)
        n = HALPR_AT(hal_node_t, n->next_ptr);
    return n;
}

/* Next pin after start (NULL = first) owned by owner. */
hal_pin_t *halpr_find_pin_by_owner(hal_comp_t *owner, hal_pin_t *start)
{
    return (hal_pin_t *)halpr_find_node_by_owner(&hal_data->pins, offsetof(hal_pin_t, owner_ptr),
                                                 owner, (hal_node_t *)start);
}

/* Next param after start (NULL = first) owned by owner. */
hal_param_t *halpr_find_param_by_owner(hal_comp_t *owner, hal_param_t *start)
{
    return (hal_param_t *)halpr_find_node_by_owner(&hal_data->params,
                                                   offsetof(hal_param_t, owner_ptr),
                                                   owner, (hal_node_t *)start);
}

/* Next funct after start (NULL = first) owned by owner. */
hal_funct_t *halpr_find_funct_by_owner(hal_comp_t *owner, hal_funct_t *start)
{
    return (hal_funct_t *)halpr_find_node_by_owner(&hal_data->functs,
                                                   offsetof(hal_funct_t, owner_ptr),
                                                   owner, (hal_node_t *)start);
}

/* Walk any list of named nodes, calling cb with per-node type/dir extracted by `get`. */
static int hal_walk(int first, void (*get)(void *, hal_type_t *, int *), hal_list_cb_t cb, void *ctx)
{
    int off, rc = 0;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    for (off = first; off && rc == 0;) {
        hal_node_t *n = SHMPTR(off);
        hal_type_t type = 0;
        int dir = 0;
        off = n->next_ptr;
        get(n, &type, &dir);
        rc = cb(n->name, type, dir, ctx);
    }
    halpr_mutex_give();
    return rc;
}

/* Type/dir of a pin for hal_walk. */
static void get_pin(void *o, hal_type_t *t, int *d) { *t = ((hal_pin_t *)o)->type; *d = ((hal_pin_t *)o)->dir; }
/* Type/dir of a param. */
static void get_param(void *o, hal_type_t *t, int *d) { *t = ((hal_param_t *)o)->type; *d = ((hal_param_t *)o)->dir; }
/* Type of a signal. */
static void get_sig(void *o, hal_type_t *t, int *d) { *t = ((hal_sig_t *)o)->type; *d = 0; }
/* Id of a comp (as dir). */
static void get_comp(void *o, hal_type_t *t, int *d) { *t = 0; *d = ((hal_comp_t *)o)->comp_id; }
/* Users of a funct (as dir). */
static void get_funct(void *o, hal_type_t *t, int *d) { *t = 0; *d = ((hal_funct_t *)o)->users; }
/* Nothing extra (threads). */
static void get_none(void *o, hal_type_t *t, int *d) { (void)o; *t = 0; *d = 0; }

/* Walk pins (see hal.h). */
int hal_list_p(hal_list_cb_t cb, void *ctx) { return hal_walk(hal_data ? hal_data->pins.list_ptr : 0, get_pin, cb, ctx); }
/* Walk params. */
int hal_list_p_s(hal_list_cb_t cb, void *ctx) { return hal_walk(hal_data ? hal_data->params.list_ptr : 0, get_param, cb, ctx); }
/* Walk signals. */
int hal_list_s(hal_list_cb_t cb, void *ctx) { return hal_walk(hal_data ? hal_data->sigs.list_ptr : 0, get_sig, cb, ctx); }
/* Walk comps, newest first. */
int hal_list_comp(hal_list_cb_t cb, void *ctx) { return hal_walk(hal_data ? hal_data->comps.list_ptr : 0, get_comp, cb, ctx); }
/* Walk functs. */
int hal_list_funct(hal_list_cb_t cb, void *ctx) { return hal_walk(hal_data ? hal_data->functs.list_ptr : 0, get_funct, cb, ctx); }
/* Walk threads, newest first. */
int hal_list_thread(hal_list_cb_t cb, void *ctx) { return hal_walk(hal_data ? hal_data->threads.list_ptr : 0, get_none, cb, ctx); }

/* Copy the public facts of a component. */
static void hal_comp_info_fill(hal_comp_t *c, hal_comp_info_t *info)
{
    info->comp_id = c->comp_id;
    info->type = c->type;
    info->ready = c->ready;
    info->pid = c->pid;
    info->owner_alive = halpr_comp_owner_alive(c);
    strcpy(info->name, c->name);
}

/* Component facts by name; 0 or -ENOENT. */
int hal_comp_by_name(const char *name, hal_comp_info_t *info)
{
    hal_comp_t *c;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    c = halpr_find_comp_by_name(name);
    if (c && info)
        hal_comp_info_fill(c, info);
    halpr_mutex_give();
    return c ? 0 : -ENOENT;
}

/* Component facts by id; 0 or -ENOENT. */
int hal_comp_by_id(int comp_id, hal_comp_info_t *info)
{
    hal_comp_t *c;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    c = halpr_find_comp_by_id(comp_id);
    if (c && info)
        hal_comp_info_fill(c, info);
    halpr_mutex_give();
    return c ? 0 : -ENOENT;
}

/* Memory use and active/recycled counts per object kind. */
int hal_statistics(hal_stats_t *st)
{
    hal_kind_t *k;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    k = hal_data->kinds;
    st->mem_used = hal_data->shmem_used;
    st->mem_total = hal_data->shmem_size;
    st->comps_active = k[HAL_KIND_COMP].active;
    st->comps_recycled = k[HAL_KIND_COMP].recycled;
    st->pins_active = k[HAL_KIND_PIN].active;
    st->pins_recycled = k[HAL_KIND_PIN].recycled;
    st->params_active = k[HAL_KIND_PARAM].active;
    st->params_recycled = k[HAL_KIND_PARAM].recycled;
    st->aliases_active = k[HAL_KIND_ALIAS].active;
    st->aliases_recycled = k[HAL_KIND_ALIAS].recycled;
    st->sigs_active = k[HAL_KIND_SIG].active;
    st->sigs_recycled = k[HAL_KIND_SIG].recycled;
    st->functs_active = k[HAL_KIND_FUNCT].active;
    st->functs_recycled = k[HAL_KIND_FUNCT].recycled;
    st->threads_active = k[HAL_KIND_THREAD].active;
    st->threads_recycled = k[HAL_KIND_THREAD].recycled;
    halpr_mutex_give();
    return 0;
}
