/* hal_bench_mem.c: HAL memory figures: bytes per pin / signal and creation time for 100,000 pins. */
#include "hal.h"
#include <stdio.h>
#include <time.h>

#define NPINS 100000
#define NSIGS 10000

/* Monotonic time in seconds. */
static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Arena bytes in total. */
static long total(void)
{
    hal_stats_t st;
    hal_statistics(&st);
    return st.mem_total;
}

/* Arena bytes in use. */
static long used(void)
{
    hal_stats_t st;
    hal_statistics(&st);
    return st.mem_used;
}

/* Print the memory and timing figures. */
int main(void)
{
    hal_float_t **cells;
    char pin[HAL_NAME_LEN + 1], sig[HAL_NAME_LEN + 1];
    long before, after_pins, after_sigs;
    double t0, t1, t2;
    int id = hal_init("bench_mem"), i;

    if (id < 0)
        return 1;
    cells = hal_malloc(NPINS * sizeof(*cells));
    before = used();
    t0 = now_s();
    for (i = 0; i < NPINS; i++)
        if (hal_pin_float_newf(HAL_IN, &cells[i], id, "bench-mem.%d.in", i) < 0)
            return 1;
    after_pins = used();
    t1 = now_s();
    for (i = 0; i < NSIGS; i++) {
        snprintf(sig, sizeof(sig), "bench-sig.%d", i);
        snprintf(pin, sizeof(pin), "bench-mem.%d.in", i);
        if (hal_signal_new(sig, HAL_FLOAT) < 0 || hal_link(pin, sig) < 0)
            return 1;
    }
    after_sigs = used();
    t2 = now_s();
    printf("pins: %d created in %.3f s, %ld bytes per pin (plus 8 for the pointer cell)\n",
           NPINS, t1 - t0, (after_pins - before) / NPINS);
    printf("signals: %d created+linked in %.3f s, %ld bytes per signal\n",
           NSIGS, t2 - t1, (after_sigs - after_pins) / NSIGS);
    printf("arena used %ld of %ld bytes\n", used(), total());
    hal_exit(id);
    return 0;
}
