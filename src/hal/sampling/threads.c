/* threads.c: realtime module that creates up to three HAL threads (rtapi.md §6). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Creates up to three HAL threads");
MODULE_LICENSE("GPL");

/* Declares the name, period (ns) and fp module parameters of thread slot n. */
#define THREAD_PARAMS(n, name_dflt, period_dflt)                            \
    static char *name##n = name_dflt;                                       \
    RTAPI_MP_STRING(name##n, "name of thread " #n);                         \
    static long period##n = period_dflt;                                    \
    RTAPI_MP_LONG(period##n, "period of thread " #n " (ns)");               \
    static int fp##n = 1;                                                   \
    RTAPI_MP_INT(fp##n, "thread " #n " uses floating point (ignored)");

THREAD_PARAMS(1, "thread1", 1000000)
THREAD_PARAMS(2, NULL, 0)
THREAD_PARAMS(3, NULL, 0)

#define NUM_THREADS 3

static int comp_id;

/* Returns non-zero when a thread slot has a usable name and period. */
static int thread_wanted(const char *name, long period_ns)
{
    return name != NULL && name[0] != '\0' && period_ns > 0;
}

/* Deletes the first `count` wanted threads of this load (error clean-up). */
static void delete_created(char *const names[], const long periods[], int count)
{
    int n;
    for (n = 0; n < count; n++) {
        if (thread_wanted(names[n], periods[n])) {
            hal_thread_delete(names[n]);
        }
    }
}

/* Module entry: registers component "threads" and creates the threads in order. */
int rtapi_app_main(void)
{
    char *names[NUM_THREADS] = { name1, name2, name3 };
    long periods[NUM_THREADS] = { period1, period2, period3 };
    int fps[NUM_THREADS] = { fp1, fp2, fp3 };
    int n, retval;

    comp_id = hal_init("threads");
    if (comp_id < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "THREADS: ERROR: hal_init() failed\n");
        return -1;
    }
    for (n = 0; n < NUM_THREADS; n++) {
        if (!thread_wanted(names[n], periods[n])) {
            continue;
        }
        retval = hal_create_thread(names[n], periods[n], fps[n]);
        if (retval < 0) {
            rtapi_print_msg(RTAPI_MSG_ERR,
                "THREADS: ERROR: could not create thread '%s'\n", names[n]);
            delete_created(names, periods, n);
            hal_exit(comp_id);
            return -1;
        }
    }
    hal_ready(comp_id);
    return 0;
}

/* Module exit: removes the component; the HAL library then drops the threads'
 * pseudo components (`<thread>.time/.tmax/.threadbeat`), the threads keep running. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
