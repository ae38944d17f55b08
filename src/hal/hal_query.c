/* hal_query.c: user-side value access by name (setp/getp/sets/gets semantics of halcmd.md §5). */
#include "hal_internal.h"

/* Copy a value of `type` between cells, touching only that type's bytes. Cells are
   accessed through their own type: a param cell (e.g. <funct>.tmax) is only aligned
   for that type, not for the whole hal_data_u union. */
static void hal_value_copy(void *dst, const void *src, hal_type_t type)
{
    switch (type) {
    case HAL_BIT: *(hal_bit_t *)dst = *(const hal_bit_t *)src; break;
    case HAL_FLOAT: *(hal_float_t *)dst = *(const hal_float_t *)src; break;
    case HAL_S32: *(hal_s32_t *)dst = *(const hal_s32_t *)src; break;
    case HAL_U32: *(hal_u32_t *)dst = *(const hal_u32_t *)src; break;
    case HAL_S64: *(hal_s64_t *)dst = *(const hal_s64_t *)src; break;
    case HAL_U64: *(hal_u64_t *)dst = *(const hal_u64_t *)src; break;
    case HAL_PORT: *(hal_port_t *)dst = *(const hal_port_t *)src; break;
    default: break;
    }
}

/* Pin-or-param value (pins first). */
int hal_get_p(const char *name, hal_type_t *type, int *dir, hal_data_u *value)
{
    hal_pin_t *pin;
    hal_param_t *param = NULL;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    pin = halpr_find_pin_by_name(name);
    if (!pin)
        param = halpr_find_param_by_name(name);
    if (pin) {
        *type = pin->type;
        *dir = pin->dir;
        value->lu = 0;
        hal_value_copy(value, halpr_pin_value(pin), pin->type);
    } else if (param) {
        *type = param->type;
        *dir = param->dir;
        value->lu = 0;
        hal_value_copy(value, halpr_param_value(param), param->type);
    }
    halpr_mutex_give();
    return (pin || param) ? 0 : -ENOENT;
}

/* setp rules for a pin; mutex held. */
static int hal_set_pin(hal_pin_t *pin, hal_type_t type, const hal_data_u *value)
{
    if (pin->type == HAL_PORT)
        return -EBADF;
    if (pin->dir == HAL_OUT || pin->signal)
        return -EACCES;
    if (pin->type != type)
        return -EBADF;
    hal_value_copy(&pin->dummysig, value, type);
    return 0;
}

/* Write a pin-or-param like setp (no lock level blocks it). */
int hal_set_p(const char *name, hal_type_t type, const hal_data_u *value)
{
    hal_pin_t *pin;
    hal_param_t *param;
    int rc = -ENOENT;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    pin = halpr_find_pin_by_name(name);
    param = pin ? NULL : halpr_find_param_by_name(name);
    if (pin) {
        rc = hal_set_pin(pin, type, value);
    } else if (param) {
        rc = param->dir == HAL_RO ? -EACCES : (param->type != type ? -EBADF : 0);
        if (rc == 0)
            hal_value_copy(halpr_param_value(param), value, type);
    }
    halpr_mutex_give();
    return rc;
}

/* Signal value (ports: buffer size in value->u) and writer count. */
int hal_get_s(const char *name, hal_type_t *type, hal_data_u *value, int *writers)
{
    hal_sig_t *sig;
    hal_data_u cell;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    sig = halpr_find_sig_by_name(name);
    if (sig) {
        *type = sig->type;
        cell = *halpr_sig_value(sig);
        if (writers)
            *writers = sig->writers;
    }
    halpr_mutex_give();
    if (!sig)
        return -ENOENT;
    value->lu = 0;
    if (*type == HAL_PORT)
        value->u = hal_port_buffer_size(&cell.p);
    else
        hal_value_copy(value, &cell, *type);
    return 0;
}

/* Allocate the buffer of a port signal once; mutex held. */
static int hal_set_port_sig(hal_sig_t *sig, unsigned size)
{
    hal_port_t port;
    int rc;

    if (halpr_sig_value(sig)->p)
        return -EISCONN;
    rc = hal_port_alloc(size, &port);
    if (rc == 0)
        halpr_sig_value(sig)->p = port;
    return rc;
}

/* Write a signal like sets (refused when it has an OUT pin; ports: allocate once). */
int hal_set_s(const char *name, hal_type_t type, const hal_data_u *value)
{
    hal_sig_t *sig;
    int rc = -ENOENT;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    sig = halpr_find_sig_by_name(name);
    if (sig && sig->type == HAL_PORT)
        rc = hal_set_port_sig(sig, value->u);
    else if (sig && sig->writers > 0)
        rc = -EACCES;
    else if (sig && sig->type != type)
        rc = -EBADF;
    else if (sig) {
        hal_value_copy(halpr_sig_value(sig), value, type);
        rc = 0;
    }
    halpr_mutex_give();
    return rc;
}

/* Address of a pin's (else param's) current value cell in this process. */
hal_data_u *hal_getref_p(const char *name, hal_type_t *type)
{
    hal_pin_t *pin;
    hal_param_t *param = NULL;
    hal_data_u *ref = NULL;

    if (!hal_data)
        return NULL;
    halpr_mutex_get();
    pin = halpr_find_pin_by_name(name);
    if (!pin)
        param = halpr_find_param_by_name(name);
    if (pin) {
        *type = pin->type;
        ref = halpr_pin_value(pin);
    } else if (param) {
        *type = param->type;
        ref = halpr_param_value(param);
    }
    halpr_mutex_give();
    return ref;
}

/* Address of a signal's value cell in this process. */
hal_data_u *hal_getref_s(const char *name, hal_type_t *type)
{
    hal_sig_t *sig;

    if (!hal_data)
        return NULL;
    halpr_mutex_get();
    sig = halpr_find_sig_by_name(name);
    if (sig)
        *type = sig->type;
    halpr_mutex_give();
    return sig ? halpr_sig_value(sig) : NULL;
}

/* LinuxCNC-style pin lookup: type, value cell, linked flag. */
int hal_get_pin_value_by_name(const char *name, hal_type_t *type, hal_data_u **data, bool *connected)
{
    hal_pin_t *pin;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    pin = halpr_find_pin_by_name(name);
    if (pin) {
        *type = pin->type;
        *data = halpr_pin_value(pin);
        if (connected)
            *connected = pin->signal != 0;
    }
    halpr_mutex_give();
    return pin ? 0 : -ENOENT;
}

/* LinuxCNC-style signal lookup: type, value cell, has-writer flag. */
int hal_get_signal_value_by_name(const char *name, hal_type_t *type, hal_data_u **data, bool *has_writers)
{
    hal_sig_t *sig;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    sig = halpr_find_sig_by_name(name);
    if (sig) {
        *type = sig->type;
        *data = halpr_sig_value(sig);
        if (has_writers)
            *has_writers = sig->writers > 0;
    }
    halpr_mutex_give();
    return sig ? 0 : -ENOENT;
}

/* LinuxCNC-style param lookup: type and value cell. */
int hal_get_param_value_by_name(const char *name, hal_type_t *type, hal_data_u **data)
{
    hal_param_t *param;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    param = halpr_find_param_by_name(name);
    if (param) {
        *type = param->type;
        *data = halpr_param_value(param);
    }
    halpr_mutex_give();
    return param ? 0 : -ENOENT;
}

/* Store the loadrt argument string of a component (for `save`). */
int halpr_set_insmod_args(const char *comp_name, const char *args)
{
    hal_comp_t *comp;
    char *copy;

    if (!hal_data)
        return -EINVAL;
    halpr_mutex_get();
    comp = halpr_find_comp_by_name(comp_name);
    copy = comp ? halpr_malloc(strlen(args) + 1) : NULL;
    if (copy) {
        strcpy(copy, args);
        comp->insmod_args = SHMOFF(copy);
    }
    halpr_mutex_give();
    return copy ? 0 : (comp ? -ENOMEM : -ENOENT);
}
