/* hal_lock.c: HAL lock levels (spec/hal.md §10): hal_set_lock / hal_get_lock. */
#include "hal_internal.h"
#include <stdio.h>

/* Set the lock bits that block later configuration calls. */
int hal_set_lock(unsigned char lock_type)
{
    if (!hal_data) {
        HAL_ERR("set_lock called before init\n");
        return -EINVAL;
    }
    hal_data->lock = lock_type;
    return 0;
}

/* Current lock bits (0 when HAL is not mapped). */
unsigned char hal_get_lock(void)
{
    if (!hal_data) {
        HAL_ERR("get_lock called before init\n");
        return 0;
    }
    return hal_data->lock;
}

/* Refuse a call before init (-EINVAL) or while any of lock_bits is set (-EPERM); locked_fmt may hold %s for what. */
int halpr_check_unlocked(const char *what, unsigned lock_bits, const char *locked_fmt)
{
    if (!hal_data) {
        HAL_ERR("%s called before init\n", what);
        return -EINVAL;
    }
    if (hal_data->lock & lock_bits) {
        char msg[2 * HAL_NAME_LEN];
        snprintf(msg, sizeof msg, locked_fmt, what);
        HAL_ERR("%s\n", msg);
        return -EPERM;
    }
    return 0;
}
