/* hal_param.c: parameter creation, removal and hal_param_set (spec/hal.md §6). */
#include "hal_internal.h"

/* Validate type, direction and name of a new param. */
static int hal_param_check_kind(const char *name, hal_type_t type, hal_param_dir_t dir)
{
    if (type < HAL_BIT || type > HAL_U64 || type == HAL_PORT) {
        HAL_ERR("param type not one of HAL_BIT, HAL_FLOAT, HAL_S32, HAL_U32, HAL_S64 or HAL_U64\n");
        return -EINVAL;
    }
    if (dir != HAL_RO && dir != HAL_RW) {
        HAL_ERR("param direction not one of HAL_RO, or HAL_RW\n");
        return -EINVAL;
    }
    return halpr_name_check("parameter", name, HAL_NAME_LEN);
}

/* Create the param record; mutex held. */
static int hal_param_insert(const char *name, hal_type_t type, hal_param_dir_t dir,
                            void *data_addr, hal_comp_t *comp)
{
    hal_param_t *param;

    if (halpr_find_param_by_name(name)) {
        HAL_ERR("duplicate parameter '%s'\n", name);
        return -EINVAL;
    }
    if (halpr_find_pin_by_name(name))
        rtapi_print_msg(RTAPI_MSG_WARN, "HAL: parameter '%s' also is the name of a pin\n", name);
    param = halpr_obj_alloc(HAL_KIND_PARAM);
    if (!param)
        return -ENOMEM;
    strcpy(param->name, name);
    param->type = type;
    param->dir = dir;
    param->owner_ptr = SHMOFF(comp);
    param->data_ptr = SHMOFF(data_addr);
    halpr_index_insert_sorted(&hal_data->params, (hal_node_t *)param);
    return 0;
}

/* Generic param constructor; data_addr must lie in HAL memory. */
int hal_param_new(const char *name, hal_type_t type, hal_param_dir_t dir, void *data_addr, int comp_id)
{
    hal_comp_t *comp;
    int rc;

    if (!hal_data) {
        HAL_ERR("param_new called before init\n");
        return -EINVAL;
    }
    if (!name) {
        HAL_ERR("param_new called without a name\n");
        return -EINVAL;
    }
    rc = hal_param_check_kind(name, type, dir);
    if (rc < 0)
        return rc;
    if (hal_data->lock & HAL_LOCK_LOAD) {
        HAL_ERR("param_new called while HAL locked\n");
        return -EPERM;
    }
    if (!SHMCHK(data_addr)) {
        HAL_ERR("param '%s': data_addr not in shared memory\n", name);
        return -EINVAL;
    }
    halpr_mutex_get();
    rc = halpr_comp_check(comp_id, "param_new", &comp);
    if (rc == 0)
        rc = hal_param_insert(name, type, dir, data_addr, comp);
    halpr_mutex_give();
    return rc;
}

/* Delete a param and its alias record; mutex held. */
void halpr_param_free(hal_param_t *param)
{
    if (param->oldname) {
        hal_oldname_t *o = SHMPTR(param->oldname);
        int *link = &hal_data->param_alias_list;
        while (*link && *link != param->oldname)
            link = &((hal_oldname_t *)SHMPTR(*link))->next_ptr;
        if (*link)
            *link = o->next_ptr;
        halpr_obj_free(HAL_KIND_ALIAS, o);
    }
    halpr_index_remove(&hal_data->params, (hal_node_t *)param);
    halpr_obj_free(HAL_KIND_PARAM, param);
}

/* Copy a value of `type` from src into a param cell. */
static void hal_param_store(void *cell, hal_type_t type, const void *src)
{
    switch (type) {
    case HAL_BIT: *(hal_bit_t *)cell = *(const hal_bit_t *)src != 0; break;
    case HAL_FLOAT: *(hal_float_t *)cell = *(const hal_float_t *)src; break;
    case HAL_S32: *(hal_s32_t *)cell = *(const hal_s32_t *)src; break;
    case HAL_U32: *(hal_u32_t *)cell = *(const hal_u32_t *)src; break;
    case HAL_S64: *(hal_s64_t *)cell = *(const hal_s64_t *)src; break;
    case HAL_U64: *(hal_u64_t *)cell = *(const hal_u64_t *)src; break;
    default: break;
    }
}

/* Set an RW param by name; blocked by HAL_LOCK_PARAMS. */
int hal_param_set(const char *name, hal_type_t type, void *value_addr)
{
    hal_param_t *param;
    int rc = 0;

    rc = halpr_check_unlocked("param_set", HAL_LOCK_PARAMS, "%s called while HAL locked");
    if (rc < 0)
        return rc;
    halpr_mutex_get();
    param = halpr_find_param_by_name(name);
    if (!param) {
        HAL_ERR("parameter '%s' not found\n", name);
        rc = -EINVAL;
    } else if (param->type != type) {
        HAL_ERR("type mismatch setting param '%s'\n", name);
        rc = -EINVAL;
    } else if (param->dir == HAL_RO) {
        HAL_ERR("param '%s' is not writable\n", name);
        rc = -EINVAL;
    } else {
        hal_param_store(halpr_param_value(param), type, value_addr);
    }
    halpr_mutex_give();
    return rc;
}
