/* hal_comp.c: components: hal_init/hal_exit/ready states, ids and the fork re-attach. */
#include "hal_internal.h"
#include <unistd.h>

static void hal_lib_release(void);

/* Find a component by id and check it may still get items; mutex held. */
int halpr_comp_check(int comp_id, const char *what, hal_comp_t **out)
{
    hal_comp_t *comp = halpr_find_comp_by_id(comp_id);

    if (!comp) {
        HAL_ERR("component %d not found\n", comp_id);
        return -EINVAL;
    }
    if (comp->ready) {
        HAL_ERR("%s called after hal_ready (%s)\n", what, comp->name);
        return -EINVAL;
    }
    *out = comp;
    return 0;
}

/* Take the HAL mutex and find a component; on failure log, release and return NULL. */
static hal_comp_t *hal_comp_lock_find(int comp_id)
{
    hal_comp_t *comp;

    halpr_mutex_get();
    comp = halpr_find_comp_by_id(comp_id);
    if (!comp) {
        halpr_mutex_give();
        HAL_ERR("component %d not found\n", comp_id);
    }
    return comp;
}

/* Create the shm record of a new component; mutex held. */
static int hal_comp_create(const char *name, int id)
{
    hal_comp_t *comp;

    if (halpr_find_comp_by_name(name)) {
        HAL_ERR("duplicate component name '%s'\n", name);
        return -EEXIST;
    }
    comp = halpr_obj_alloc(HAL_KIND_COMP);
    if (!comp)
        return -ENOMEM;
    strcpy(comp->name, name);
    comp->comp_id = id;
    comp->type = hal_proc_is_rt ? HAL_COMP_RT : HAL_COMP_USER;
    comp->pid = hal_proc_is_rt ? 0 : getpid();
    comp->owner_start = hal_proc_is_rt ? 0 : halpr_process_start(getpid());
    comp->shmem_base = hal_shmem_base;
    halpr_index_insert_head(&hal_data->comps, (hal_node_t *)comp);
    return 0;
}

/* Register a component; returns its id (>0) or a negative errno. */
int hal_init(const char *name)
{
    int id, rc;

    if (!name) {
        HAL_ERR("no component name\n");
        return -EINVAL;
    }
    if (halpr_name_check("component", name, HAL_NAME_LEN) < 0) {
        return -EINVAL;
    }
    rc = hal_proc_is_rt ? 0 : hal_attach_user();
    if (rc < 0)
        return rc;
    id = rtapi_init(name);
    if (id < 0) {
        HAL_ERR("rtapi init failed for '%s'\n", name);
        return -EINVAL;
    }
    halpr_mutex_get();
    rc = hal_comp_create(name, id);
    halpr_mutex_give();
    if (rc < 0) {
        rtapi_exit(id);
        return rc;
    }
    hal_proc_comps++;
    return id;
}

/* Remove everything a component owns (functs, pins, params); mutex held. */
void halpr_comp_free_items(hal_comp_t *comp)
{
    hal_funct_t *f;
    hal_pin_t *pin;
    hal_param_t *param;

    while ((f = halpr_find_funct_by_owner(comp, NULL)))
        halpr_funct_free(f);
    while ((pin = halpr_find_pin_by_owner(comp, NULL)))
        halpr_pin_free(pin);
    while ((param = halpr_find_param_by_owner(comp, NULL)))
        halpr_param_free(param);
    if (comp->is_thread_comp)
        halpr_thread_park(comp);
    else if (comp->type == HAL_COMP_RT)
        halpr_thread_creator_exit(comp);
}

/* Remove a component with its pins, params and functs. */
int hal_exit(int comp_id)
{
    hal_comp_t *comp;

    if (!hal_data) {
        HAL_ERR("exit called before init\n");
        return -EINVAL;
    }
    comp = hal_comp_lock_find(comp_id);
    if (!comp)
        return -EINVAL;
    halpr_comp_free_items(comp);
    halpr_index_remove(&hal_data->comps, (hal_node_t *)comp);
    halpr_obj_free(HAL_KIND_COMP, comp);
    halpr_mutex_give();
    rtapi_exit(comp_id);
    if (hal_proc_comps > 0)
        hal_proc_comps--;
    hal_lib_release();
    return 0;
}

/* Change a component's ready flag; `strict` refuses a no-op change. */
static int hal_comp_set_ready(int comp_id, int ready, int strict)
{
    hal_comp_t *comp;
    int rc = 0;

    if (!hal_data) {
        HAL_ERR("ready called before init\n");
        return -EINVAL;
    }
    halpr_mutex_get();
    comp = halpr_find_comp_by_id(comp_id);
    if (!comp) {
        HAL_ERR("component %d not found\n", comp_id);
        rc = -EINVAL;
    } else if (strict && comp->ready == ready) {
        HAL_ERR("component '%s' already %s\n", comp->name, ready ? "ready" : "unready");
        rc = -EINVAL;
    } else {
        comp->ready = ready;
    }
    halpr_mutex_give();
    return rc;
}

/* Mark a component ready. */
int hal_ready(int comp_id)
{
    return hal_comp_set_ready(comp_id, 1, 1);
}

/* Make a ready component initializing again (error if already unready). */
int hal_unready(int comp_id)
{
    return hal_comp_set_ready(comp_id, 0, 1);
}

/* Make a component initializing again (no error if already unready). */
int hal_set_unready(int comp_id)
{
    return hal_comp_set_ready(comp_id, 0, 0);
}

/* Name of a component, or NULL. */
const char *hal_comp_name(int comp_id)
{
    hal_comp_t *comp;

    if (!hal_data)
        return NULL;
    halpr_mutex_get();
    comp = halpr_find_comp_by_id(comp_id);
    halpr_mutex_give();
    return comp ? comp->name : NULL;
}

/* Register a component's instance constructor (newinst). */
int hal_set_constructor(int comp_id, hal_constructor_t make)
{
    hal_comp_t *comp;

    if (!hal_data)
        return -EINVAL;
    comp = hal_comp_lock_find(comp_id);
    if (!comp)
        return -EINVAL;
    comp->make = make;
    halpr_mutex_give();
    return 0;
}

static int hal_lib_explicit;  /* hal_lib_init was called: keep the mapping after hal_exit */

/* Map HAL memory without a component (one id for the library attach). */
int hal_lib_init(void)
{
    int rc = hal_proc_is_rt ? 0 : hal_attach_user();
    if (rc == 0)
        hal_lib_explicit = 1;
    return rc;
}

/* Unmap HAL memory when this user process has no components left. */
void hal_lib_exit(void)
{
    hal_lib_explicit = 0;
    hal_lib_release();
}

/* Unmap unless components or an explicit hal_lib_init still need the mapping. */
static void hal_lib_release(void)
{
    if (hal_proc_is_rt || hal_proc_comps > 0 || hal_lib_explicit || !hal_data)
        return;
    hal_shm_detach();
    if (hal_proc_lib_id > 0)
        rtapi_exit(hal_proc_lib_id);
    hal_proc_lib_id = 0;
}

/* Non-zero when this process has HAL memory mapped. */
int hal_is_init(void)
{
    return hal_data != NULL;
}

/* LinuxCNC halcmd re-attaches around fork: +2 ids, comp moves to the head. */
int hal_reattach_for_fork(int comp_id)
{
    hal_comp_t *comp;
    int lib_id, new_id;

    if (!hal_data)
        return -EINVAL;
    comp = hal_comp_lock_find(comp_id);
    if (!comp)
        return -EINVAL;
    lib_id = rtapi_init("HAL_LIB");
    new_id = rtapi_init(comp->name);
    if (lib_id < 0 || new_id < 0) {
        halpr_mutex_give();
        HAL_ERR("rtapi init failed while re-attaching '%s'\n", comp->name);
        return -EINVAL;
    }
    rtapi_exit(comp_id);
    if (hal_proc_lib_id > 0)
        rtapi_exit(hal_proc_lib_id);
    hal_proc_lib_id = lib_id;
    comp->comp_id = new_id;
    halpr_index_remove(&hal_data->comps, (hal_node_t *)comp);
    halpr_index_insert_head(&hal_data->comps, (hal_node_t *)comp);
    halpr_mutex_give();
    return new_id;
}
