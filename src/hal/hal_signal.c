/* hal_signal.c: signals, linking and unlinking with the rules of spec/hal.md §7. */
#include "hal_internal.h"

/* Point the owner's pointer cell of a pin at a value cell (offset). */
static void hal_pin_point(hal_pin_t *pin, int cell_off)
{
    hal_comp_t *owner = halpr_owner(pin->owner_ptr);
    void **cell = SHMPTR(pin->data_ptr_addr);
    __atomic_store_n(cell, (void *)(owner->shmem_base + cell_off), __ATOMIC_RELEASE);
}

/* Insert pin into the signal's name-ordered pin list. */
void halpr_sig_pin_insert(hal_sig_t *sig, hal_pin_t *pin)
{
    int *link = &sig->pins_ptr;
    while (*link && strcmp(((hal_pin_t *)SHMPTR(*link))->name, pin->name) < 0)
        link = &((hal_pin_t *)SHMPTR(*link))->sig_next;
    pin->sig_next = *link;
    *link = SHMOFF(pin);
}

/* Remove pin from the signal's pin list. */
void halpr_sig_pin_remove(hal_sig_t *sig, hal_pin_t *pin)
{
    int *link = &sig->pins_ptr;
    while (*link && *link != SHMOFF(pin))
        link = &((hal_pin_t *)SHMPTR(*link))->sig_next;
    if (*link)
        *link = pin->sig_next;
    pin->sig_next = 0;
}

/* Unlink a linked pin: it keeps the signal's value (ports become empty); mutex held. */
void halpr_unlink_pin(hal_pin_t *pin)
{
    hal_sig_t *sig = SHMPTR(pin->signal);

    if (pin->type == HAL_PORT)
        pin->dummysig.lu = 0;
    else
        pin->dummysig = *halpr_sig_value(sig);
    hal_pin_point(pin, SHMOFF(&pin->dummysig));
    if (pin->dir == HAL_OUT)
        sig->writers--;
    else
        sig->readers--;
    if (pin->dir == HAL_IO)
        sig->bidirs--;
    halpr_sig_pin_remove(sig, pin);
    pin->signal = 0;
}

/* Create a signal of a type. */
int hal_signal_new(const char *name, hal_type_t type)
{
    hal_sig_t *sig;
    int rc;

    rc = halpr_check_unlocked("signal_new", HAL_LOCK_CONFIG, "%s called while HAL is locked");
    if (rc < 0)
        return rc;
    rc = halpr_name_check("signal", name, HAL_NAME_LEN);
    if (rc < 0)
        return rc;
    if (type < HAL_BIT || type > HAL_U64) {
        HAL_ERR("signal type not one of HAL_BIT, HAL_FLOAT, HAL_S32, HAL_U32, HAL_S64, HAL_U64 or HAL_PORT\n");
        return -EINVAL;
    }
    halpr_mutex_get();
    if (halpr_find_sig_by_name(name)) {
        halpr_mutex_give();
        HAL_ERR("duplicate signal '%s'\n", name);
        return -EINVAL;
    }
    sig = halpr_obj_alloc(HAL_KIND_SIG);
    if (!sig) {
        halpr_mutex_give();
        return -ENOMEM;
    }
    strcpy(sig->name, name);
    sig->type = type;
    sig->data_ptr = SHMOFF(&sig->value);
    halpr_index_insert_sorted(&hal_data->sigs, (hal_node_t *)sig);
    halpr_mutex_give();
    return 0;
}

/* Delete a signal; its pins are unlinked and keep the value. */
int hal_signal_delete(const char *name)
{
    hal_sig_t *sig;
    int rc;

    rc = halpr_check_unlocked("signal_delete", HAL_LOCK_CONFIG,
                              "%s called while HAL is locked");
    if (rc < 0)
        return rc;
    halpr_mutex_get();
    sig = halpr_find_sig_by_name(name);
    if (!sig) {
        halpr_mutex_give();
        HAL_ERR("signal '%s' not found\n", name);
        return -EINVAL;
    }
    while (sig->pins_ptr)
        halpr_unlink_pin(SHMPTR(sig->pins_ptr));
    halpr_index_remove(&hal_data->sigs, (hal_node_t *)sig);
    halpr_obj_free(HAL_KIND_SIG, sig);
    halpr_mutex_give();
    return 0;
}

/* Check the writer/reader rules for linking pin to sig (after type match). */
static int hal_link_check_dir(hal_pin_t *pin, hal_sig_t *sig)
{
    if (pin->dir == HAL_OUT && (sig->writers > 0 || sig->bidirs > 0)) {
        HAL_ERR("signal '%s' already has output or I/O pin(s)\n", sig->name);
        return -EINVAL;
    }
    if (pin->dir == HAL_IO && sig->type == HAL_PORT) {
        HAL_ERR("signal '%s' is a port and cannot have I/O pin(s)\n", sig->name);
        return -EINVAL;
    }
    if (pin->dir == HAL_IO && sig->writers > 0) {
        HAL_ERR("signal '%s' already has output pin\n", sig->name);
        return -EINVAL;
    }
    if (pin->dir == HAL_IN && sig->type == HAL_PORT && sig->readers > 0) {
        HAL_ERR("signal '%s' can only have one input pin\n", sig->name);
        return -EINVAL;
    }
    return 0;
}

/* All link checks in spec order; 1 = already linked here, 0 = go, <0 error. */
static int hal_link_check(const char *pin_name, const char *sig_name, hal_pin_t **pp, hal_sig_t **sp)
{
    hal_pin_t *pin = halpr_find_pin_by_name(pin_name);
    hal_sig_t *sig;

    if (!pin) {
        HAL_ERR("pin '%s' not found\n", pin_name);
        return -EINVAL;
    }
    sig = halpr_find_sig_by_name(sig_name);
    if (!sig) {
        HAL_ERR("signal '%s' not found\n", sig_name);
        return -EINVAL;
    }
    if (pin->signal == SHMOFF(sig)) {
        rtapi_print_msg(RTAPI_MSG_WARN, "HAL: Warning: pin '%s' already linked to '%s'\n",
                        pin_name, sig_name);
        return 1;
    }
    if (pin->signal) {
        HAL_ERR("pin '%s' is linked to '%s', cannot link to '%s'\n", pin_name,
                ((hal_sig_t *)SHMPTR(pin->signal))->name, sig_name);
        return -EINVAL;
    }
    if (pin->type != sig->type) {
        HAL_ERR("type mismatch '%s' <- '%s'\n", pin_name, sig_name);
        return -EINVAL;
    }
    *pp = pin;
    *sp = sig;
    return hal_link_check_dir(pin, sig);
}

/* Join pin and signal: value inheritance, counters, pointer, pin list. */
static void hal_link_do(hal_pin_t *pin, hal_sig_t *sig)
{
    if (pin->type != HAL_PORT && sig->writers == 0 && sig->bidirs == 0 &&
        (pin->dir != HAL_IN || sig->readers == 0))
        *halpr_sig_value(sig) = pin->dummysig;
    if (pin->dir == HAL_OUT)
        sig->writers++;
    else
        sig->readers++;
    if (pin->dir == HAL_IO)
        sig->bidirs++;
    pin->signal = SHMOFF(sig);
    halpr_sig_pin_insert(sig, pin);
    hal_pin_point(pin, sig->data_ptr);
}

/* Link a pin to a signal. */
int hal_link(const char *pin_name, const char *sig_name)
{
    hal_pin_t *pin = NULL;
    hal_sig_t *sig = NULL;
    int rc;

    rc = halpr_check_unlocked("link", HAL_LOCK_CONFIG, "%s called while HAL locked");
    if (rc < 0)
        return rc;
    halpr_mutex_get();
    rc = hal_link_check(pin_name, sig_name, &pin, &sig);
    if (rc == 0)
        hal_link_do(pin, sig);
    halpr_mutex_give();
    return rc < 0 ? rc : 0;
}

/* Unlink a pin from its signal (no-op when unlinked). */
int hal_unlink(const char *pin_name)
{
    hal_pin_t *pin;
    int rc;

    rc = halpr_check_unlocked("unlink", HAL_LOCK_CONFIG, "%s called while HAL locked");
    if (rc < 0)
        return rc;
    halpr_mutex_get();
    pin = halpr_find_pin_by_name(pin_name);
    if (!pin) {
        halpr_mutex_give();
        HAL_ERR("pin '%s' not found\n", pin_name);
        return -EINVAL;
    }
    if (pin->signal)
        halpr_unlink_pin(pin);
    halpr_mutex_give();
    return 0;
}
