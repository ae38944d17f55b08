/* hal_bench.c: realtime benchmark module: one thread running `count` trivial functs, averaged thread time. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "hal_priv.h"

MODULE_LICENSE("GPL");

static int count = 1000;
RTAPI_MP_INT(count, "number of trivial functions");
static long period = 1000000;
RTAPI_MP_LONG(period, "thread period in ns (0: no thread, functs only)");

/* Accumulated thread times (in HAL memory). */
struct bench_state {
    hal_s64_t *sum_ns;      /* sum of bench-thread.time over sampled cycles */
    hal_s32_t *cycles;      /* sampled cycles */
    hal_s32_t *min_ns;      /* smallest thread time seen (least disturbed cycle) */
    hal_s32_t *thread_time; /* bench-thread.time value cell (RT address) */
};

static int comp_id;
static struct bench_state *st;

/* The trivial function being measured. */
static void nop_funct(void *arg, long period_ns)
{
    (void)arg;
    (void)period_ns;
}

/* First funct of each cycle: add the previous cycle's thread time. */
static void sample_funct(void *arg, long period_ns)
{
    struct bench_state *s = arg;
    (void)period_ns;
    if (*s->thread_time > 0) {
        *s->sum_ns += *s->thread_time;
        *s->cycles += 1;
        if (*s->min_ns == 0 || *s->thread_time < *s->min_ns)
            *s->min_ns = *s->thread_time;
    }
}

/* Export the trivial functs hal-bench.0 .. count-1. */
static int bench_functs(void)
{
    int i, rc = 0;

    for (i = 0; i < count && rc == 0; i++)
        rc = hal_export_functf(nop_funct, NULL, 0, 0, comp_id, "hal-bench.%d", i);
    return rc;
}

/* Schedule hal-bench.0 .. count-1 after the sampler. */
static int bench_addf(void)
{
    char name[HAL_NAME_LEN + 1];
    int i, rc = hal_add_funct_to_thread("hal-bench.sample", "bench-thread", 1);

    for (i = 0; i < count && rc == 0; i++) {
        rtapi_snprintf(name, sizeof(name), "hal-bench.%d", i);
        rc = hal_add_funct_to_thread(name, "bench-thread", -1);
    }
    return rc;
}

/* Create the thread, the sampler and its pins. */
static int bench_thread(void)
{
    hal_pin_t *pin;
    int rc = hal_pin_s64_new("hal-bench.sum-ns", HAL_OUT, &st->sum_ns, comp_id);

    if (rc == 0)
        rc = hal_pin_s32_new("hal-bench.cycles", HAL_OUT, &st->cycles, comp_id);
    if (rc == 0)
        rc = hal_pin_s32_new("hal-bench.min-ns", HAL_OUT, &st->min_ns, comp_id);
    if (rc == 0)
        rc = hal_export_funct("hal-bench.sample", sample_funct, st, 0, 0, comp_id);
    if (rc == 0)
        rc = hal_create_thread("bench-thread", period, 0);
    if (rc < 0)
        return rc;
    halpr_mutex_get();
    pin = halpr_find_pin_by_name("bench-thread.time");
    st->thread_time = pin ? &halpr_pin_value(pin)->s : NULL;
    halpr_mutex_give();
    return st->thread_time ? bench_addf() : -ENOENT;
}

/* Build everything; the functs run once `start` is given. */
int rtapi_app_main(void)
{
    int rc;

    comp_id = hal_init("hal_bench");
    if (comp_id < 0)
        return comp_id;
    st = hal_malloc(sizeof(*st));
    rc = st ? bench_functs() : -ENOMEM;
    if (rc == 0 && period > 0)
        rc = bench_thread();
    if (rc < 0) {
        hal_exit(comp_id);
        return rc;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component (functs leave the thread). */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
