/* rtapi_mutex.h: a spin mutex on bit 0 of an unsigned long (works in shared memory). */
#ifndef RTAPI_MUTEX_H
#define RTAPI_MUTEX_H
#include <sched.h>
#include "rtapi_bitops.h"

typedef unsigned long rtapi_mutex_t;

/* Release the mutex. */
static inline void rtapi_mutex_give(volatile rtapi_mutex_t *mutex)
{
    rtapi_clear_bit(0, mutex);
}

/* Take the mutex if free: 0 on success, non-zero when it is held. */
static inline int rtapi_mutex_try(volatile rtapi_mutex_t *mutex)
{
    return rtapi_test_and_set_bit(0, mutex);
}

/* Take the mutex, yielding the CPU while another holder has it. */
static inline void rtapi_mutex_get(volatile rtapi_mutex_t *mutex)
{
    while (rtapi_test_and_set_bit(0, mutex))
        sched_yield();
}
#endif
