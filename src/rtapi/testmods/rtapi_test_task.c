/* rtapi_test_task.c: test module checking period arithmetic, catch-up and overrun counts. */
#include "rtapi.h"
#include "rtapi_app.h"

static long period = 1000000;
RTAPI_MP_LONG(period, "task period in ns");
static int cycles = 100;
RTAPI_MP_INT(cycles, "cycles to check before reporting");
static int stall;
RTAPI_MP_INT(stall, "at cycle 3, overrun this many whole periods (plus a half)");

static int module_id, task_id = -1;

/* Busy-wait until the absolute time t. */
static void spin_until(long long t)
{
    while (rtapi_get_time() < t)
        ;
}

/* Print the verdict of a finished run. */
static void report(int calls, long long span, int mismatches, int early)
{
    rtapi_task_stats_t st;

    rtapi_task_get_stats(rtapi_task_self(), &st);
    rtapi_print("task: %d calls, reference span %lld periods, mismatches %d, early %d, "
                "cycles counted %s, overruns >= %d: %s\n", calls, span, mismatches, early,
                st.cycles == (unsigned long long)calls ? "yes" : "no", stall,
                st.overruns >= (unsigned long long)stall ? "yes" : "no");
}

/* Each cycle's reference must be first + n*period and no wake-up may be early. */
static void check_task(void *arg)
{
    long long first = rtapi_task_pll_get_reference(), ref = first;
    int calls = 0, mismatches = 0, early = 0;

    (void)arg;
    for (int n = 0; n < cycles; n++) {
        ref = rtapi_task_pll_get_reference();
        if (ref != first + (long long)n * period)
            mismatches++;
        if (n == 3 && stall > 0)
            spin_until(ref + (long long)stall * period + period / 2);
        calls++;
        rtapi_wait();
        if (rtapi_get_time() < ref)
            early++;
    }
    report(calls, (ref - first) / period, mismatches, early);
    for (;;)
        rtapi_wait();
}

/* Create and start the checking task. */
int rtapi_app_main(void)
{
    int rc;

    module_id = rtapi_init("rtapi_test_task");
    task_id = rtapi_task_new(check_task, NULL, rtapi_prio_highest(), module_id, 0, 0);
    if (task_id < 0)
        return task_id;
    rc = rtapi_task_start(task_id, (unsigned long)period);
    if (rc < 0)
        rtapi_task_delete(task_id);
    return rc;
}

/* Stop the task. */
void rtapi_app_exit(void)
{
    rtapi_task_delete(task_id);
    rtapi_exit(module_id);
}
