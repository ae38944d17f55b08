/* hal_thread_run.c: the realtime cycle of a HAL thread and its cheap nanosecond clock. */
#include "hal_internal.h"
#include <stdio.h>
#include <time.h>
#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#define HAL_HAVE_TSC 1
#else
#define HAL_HAVE_TSC 0
#endif

static int hal_clock_tsc;              /* 1: timing uses the TSC */
static unsigned long long hal_tsc_mult; /* ns per tick, 0.32 fixed point (TSC >= 1 GHz) */

/* Raw clock ticks: the TSC when tsc is set, else ns from CLOCK_MONOTONIC. */
static inline unsigned long long hal_ticks(int tsc)
{
#if HAL_HAVE_TSC
    if (tsc)
        return __rdtsc();
#else
    (void)tsc;
#endif
    return (unsigned long long)rtapi_get_time();
}

/* Tick difference to ns, clamped to the s32 range of the .time items (mult < 2^32);
   written so the compiler can use conditional moves instead of branches. */
static inline __attribute__((always_inline)) int32_t hal_ticks_ns(unsigned long long d, int tsc)
{
    d = d > 0xffffffffULL ? 0xffffffffULL : d;
    if (tsc)
        d = (d * hal_tsc_mult) >> 32;
    return (int32_t)(d > 0x7fffffffULL ? 0x7fffffffULL : d);
}

/* 1 when /proc/cpuinfo says the TSC runs at a constant rate. */
static int hal_tsc_is_constant(void)
{
    char line[4096];
    int ok = 0;
    FILE *f = fopen("/proc/cpuinfo", "r");

    if (!f)
        return 0;
    while (!ok && fgets(line, sizeof(line), f))
        ok = strncmp(line, "flags", 5) == 0 && strstr(line, " constant_tsc") &&
             strstr(line, " nonstop_tsc");
    fclose(f);
    return ok;
}

/* Measure the TSC rate against CLOCK_MONOTONIC over 20 ms (done once at RT start-up). */
void hal_clock_calibrate(void)
{
#if HAL_HAVE_TSC
    struct timespec ts = {0, 20000000};
    long long t0, t1;
    unsigned long long c0, c1;

    if (!hal_tsc_is_constant())
        return;
    t0 = rtapi_get_time();
    c0 = __rdtsc();
    nanosleep(&ts, NULL);
    t1 = rtapi_get_time();
    c1 = __rdtsc();
    if (c1 <= c0 || t1 <= t0)
        return;
    hal_tsc_mult = (unsigned long long)(((unsigned __int128)(t1 - t0) << 32) / (c1 - c0));
    hal_clock_tsc = hal_tsc_mult > 0 && hal_tsc_mult <= 0xffffffffULL;
#endif
}

/* Store a funct's time and update its tmax / tmax-increased without branches. */
static inline __attribute__((always_inline)) void hal_funct_timed(hal_funct_timing_t *tm,
                                                                  int32_t d)
{
    int32_t m = tm->tmax;
    int grew = d > m;

    *tm->time = d;
    tm->tmax = grew ? d : m;
    tm->tmax_increased = grew;
}

/* One cyclic pass: every funct with the nominal period; one clock read per funct
   boundary ends one funct's time and starts the next one's. tsc is a constant in
   each of the two expansions, so the loop holds no clock-kind test. */
static inline __attribute__((always_inline)) void hal_thread_pass(hal_thread_t *t, int tsc)
{
    char *const base = hal_shmem_base;
    const long period = t->period;
    unsigned long long start = hal_ticks(tsc), t0 = start, t1;
    int off = __atomic_load_n(&t->funct_list, __ATOMIC_ACQUIRE);
    int32_t d;

    while (off) {
        hal_funct_entry_t *e = (hal_funct_entry_t *)(base + off);
        e->funct(e->arg, period);
        t1 = hal_ticks(tsc);
        hal_funct_timed(e->timing, hal_ticks_ns(t1 - t0, tsc));
        t0 = t1;
        off = __atomic_load_n(&e->next_ptr, __ATOMIC_ACQUIRE);
    }
    d = hal_ticks_ns(t0 - start, tsc);
    **t->runtime = d;
    if (d > *t->maxtime)
        *t->maxtime = d;
    **t->threadbeat += 1;
}

/* One cyclic pass timed with the TSC or with CLOCK_MONOTONIC. */
static void hal_thread_cycle(hal_thread_t *t)
{
    if (hal_clock_tsc)
        hal_thread_pass(t, 1);
    else
        hal_thread_pass(t, 0);
}

/* The init cycle: run the init list once instead of the cyclic list. */
static void hal_thread_init_cycle(hal_thread_t *t)
{
    int off = __atomic_load_n(&t->init_list, __ATOMIC_ACQUIRE);

    while (off) {
        hal_funct_entry_t *e = (hal_funct_entry_t *)(hal_shmem_base + off);
        e->funct(e->arg, t->period);
        off = __atomic_load_n(&e->next_ptr, __ATOMIC_ACQUIRE);
    }
    t->init_reap = 1;
    __atomic_store_n(&t->init_done, 1, __ATOMIC_RELEASE);
    rtapi_task_self_resync();
}

/* Free the executed init list when the HAL mutex happens to be free (never waits). */
static void hal_thread_reap_init(hal_thread_t *t)
{
    if (!halpr_mutex_try())
        return;
    halpr_entry_list_free(&t->init_list);
    t->init_reap = 0;
    halpr_mutex_give();
}

/* Task body of every HAL thread: tick each period, run functs while threads_running. */
void hal_thread_task(void *arg)
{
    hal_thread_t *t = arg;

    for (;;) {
        if (__atomic_load_n(&hal_data->threads_running, __ATOMIC_ACQUIRE)) {
            __atomic_store_n(&t->in_cycle, 1, __ATOMIC_SEQ_CST);
            if (!t->init_done)
                hal_thread_init_cycle(t);
            else
                hal_thread_cycle(t);
            __atomic_add_fetch(&t->cycle_seq, 1, __ATOMIC_SEQ_CST);
            __atomic_store_n(&t->in_cycle, 0, __ATOMIC_RELEASE);
        }
        if (t->init_reap)
            hal_thread_reap_init(t);
        rtapi_wait();
    }
}
