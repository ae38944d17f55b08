/* hal_item_new.c: printf-style naming and HAL-allocated cells shared by the pin and param constructors. */
#include "hal_internal.h"

/* Create a pin (is_pin; addr is the pointer cell) or a param (addr is the value) named name. */
static int halpr_item_new(int is_pin, hal_type_t type, int dir, void *addr, int comp_id,
                          const char *name)
{
    if (is_pin)
        return hal_pin_new(name, type, (hal_pin_dir_t)dir, (void **)addr, comp_id);
    return hal_param_new(name, type, (hal_param_dir_t)dir, addr, comp_id);
}

/* Create a pin or param whose name is printf(fmt, ap) on caller-supplied storage addr. */
int halpr_item_new_va(int is_pin, hal_type_t type, int dir, void *addr, int comp_id,
                      const char *fmt, va_list ap)
{
    char name[HAL_NAME_LEN + 1];
    int rc = halpr_name_fmt(name, fmt, ap);

    if (rc < 0)
        return rc;
    return halpr_item_new(is_pin, type, dir, addr, comp_id, name);
}

/* New API core: name it, allocate the pointer (pin) or value (param) cell, create, hand out the cell. */
int halpr_item_new_ref(int is_pin, hal_type_t type, int dir, void **ref, int comp_id,
                       const char *fmt, va_list ap)
{
    char name[HAL_NAME_LEN + 1];
    void *cell;
    int rc = halpr_name_fmt(name, fmt, ap);

    if (rc < 0)
        return rc;
    cell = hal_malloc(is_pin ? sizeof(void *) : sizeof(hal_data_u));
    if (!cell)
        return -ENOMEM;
    rc = halpr_item_new(is_pin, type, dir, cell, comp_id, name);
    if (rc < 0)
        return rc;
    *ref = cell;
    return 0;
}
