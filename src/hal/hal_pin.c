/* hal_pin.c: pin creation and removal (spec/hal.md §5). */
#include "hal_internal.h"
#include <stdio.h>

/* Format a HAL name into buf[HAL_NAME_LEN+1]; -ENOMEM when it overflows. */
int halpr_name_fmt(char *buf, const char *fmt, va_list ap)
{
    int len = vsnprintf(buf, HAL_NAME_LEN + 1, fmt, ap);
    if (len < 0 || len > HAL_NAME_LEN) {
        HAL_ERR("length %d too long for name starting '%s'\n", len, buf);
        return -ENOMEM;
    }
    return 0;
}

/* Validate type and direction of a new pin. */
static int hal_pin_check_kind(const char *name, hal_type_t type, hal_pin_dir_t dir)
{
    if (type < HAL_BIT || type > HAL_U64) {
        HAL_ERR("pin type not one of HAL_BIT, HAL_FLOAT, HAL_S32, HAL_U32, HAL_S64, HAL_U64 or HAL_PORT\n");
        return -EINVAL;
    }
    if (dir != HAL_IN && dir != HAL_OUT && dir != HAL_IO) {
        HAL_ERR("pin direction not one of HAL_IN, HAL_OUT, or HAL_IO\n");
        return -EINVAL;
    }
    if (type == HAL_PORT && dir == HAL_IO) {
        HAL_ERR("pin '%s': port pins must be HAL_IN or HAL_OUT\n", name);
        return -EINVAL;
    }
    return halpr_name_check("pin", name, HAL_NAME_LEN);
}

/* Create the pin record and point the owner's cell at its dummy; mutex held. */
static int hal_pin_insert(const char *name, hal_type_t type, hal_pin_dir_t dir,
                          void **data_ptr_addr, hal_comp_t *comp)
{
    hal_pin_t *pin;

    if (halpr_find_pin_by_name(name)) {
        HAL_ERR("duplicate pin '%s'\n", name);
        return -EINVAL;
    }
    if (halpr_find_param_by_name(name))
        rtapi_print_msg(RTAPI_MSG_WARN, "HAL: pin '%s' also is the name of a parameter\n", name);
    pin = halpr_obj_alloc(HAL_KIND_PIN);
    if (!pin)
        return -ENOMEM;
    strcpy(pin->name, name);
    pin->type = type;
    pin->dir = dir;
    pin->owner_ptr = SHMOFF(comp);
    pin->data_ptr_addr = SHMOFF(data_ptr_addr);
    *data_ptr_addr = comp->shmem_base + SHMOFF(&pin->dummysig);
    halpr_index_insert_sorted(&hal_data->pins, (hal_node_t *)pin);
    return 0;
}

/* Checks shared by all pin constructors, then insertion. */
int halpr_pin_create(const char *name, hal_type_t type, hal_pin_dir_t dir,
                     void **data_ptr_addr, int comp_id)
{
    hal_comp_t *comp;
    int rc;

    if (!hal_data) {
        HAL_ERR("pin_new called before init\n");
        return -EINVAL;
    }
    rc = hal_pin_check_kind(name, type, dir);
    if (rc < 0)
        return rc;
    if (hal_data->lock & HAL_LOCK_LOAD) {
        HAL_ERR("pin_new called while HAL locked\n");
        return -EPERM;
    }
    if (!SHMCHK(data_ptr_addr)) {
        HAL_ERR("pin '%s': data_ptr_addr not in shared memory\n", name);
        return -EINVAL;
    }
    halpr_mutex_get();
    rc = halpr_comp_check(comp_id, "pin_new", &comp);
    if (rc == 0)
        rc = hal_pin_insert(name, type, dir, data_ptr_addr, comp);
    halpr_mutex_give();
    return rc;
}

/* Generic pin constructor. */
int hal_pin_new(const char *name, hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr, int comp_id)
{
    if (!name) {
        HAL_ERR("pin_new called without a name\n");
        return -EINVAL;
    }
    return halpr_pin_create(name, type, dir, data_ptr_addr, comp_id);
}

/* Delete a pin: unlink it, drop its alias record, free it; mutex held. */
void halpr_pin_free(hal_pin_t *pin)
{
    if (pin->signal)
        halpr_unlink_pin(pin);
    if (pin->oldname) {
        hal_oldname_t *o = SHMPTR(pin->oldname);
        int *link = &hal_data->pin_alias_list;
        while (*link && *link != pin->oldname)
            link = &((hal_oldname_t *)SHMPTR(*link))->next_ptr;
        if (*link)
            *link = o->next_ptr;
        halpr_obj_free(HAL_KIND_ALIAS, o);
    }
    halpr_index_remove(&hal_data->pins, (hal_node_t *)pin);
    halpr_obj_free(HAL_KIND_PIN, pin);
}
