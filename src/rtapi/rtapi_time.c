/* rtapi_time.c: monotonic clock, the timer period and short delays. */
#include <time.h>
#include "rtapi.h"

#define RTAPI_DELAY_MAX_NS 10000

static long clock_period_ns;

/* CLOCK_MONOTONIC in ns. */
long long int rtapi_get_time(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Clock units are ns in uspace, so clocks equal time. */
long long int rtapi_get_clocks(void)
{
    return rtapi_get_time();
}

/* 0 returns the period; the first non-zero call sets it; later ones fail. */
long int rtapi_clock_set_period(long int nsecs)
{
    if (nsecs == 0)
        return clock_period_ns;
    if (clock_period_ns != 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "attempt to set period twice\n");
        return -EINVAL;
    }
    if (nsecs < 0)
        return -EINVAL;
    clock_period_ns = nsecs;
    return clock_period_ns;
}

/* Busy-wait nsec ns (capped at rtapi_delay_max()). */
void rtapi_delay(long int nsec)
{
    long long end;

    if (nsec > RTAPI_DELAY_MAX_NS)
        nsec = RTAPI_DELAY_MAX_NS;
    end = rtapi_get_time() + nsec;
    while (rtapi_get_time() < end)
        ;
}

/* Longest delay rtapi_delay honours. */
long int rtapi_delay_max(void)
{
    return RTAPI_DELAY_MAX_NS;
}
