/* hist_unit.c: unit test of the latency histogram: counts, percentiles and text rows. */
#include <stdio.h>
#include <stdlib.h>
#include "latency_hist.h"

static latency_hist_t hist;

/* Print the percentile and range-count figures for the current samples. */
static void figures(void)
{
    printf("samples %llu min %lld max %lld overflow %llu\n", hist.samples, hist.min_ns,
           hist.max_ns, hist.overflow);
    printf("p50 %lld p99 %lld\n", latency_hist_percentile(&hist, 0.5),
           latency_hist_percentile(&hist, 0.99));
    printf("count [0,1000) %llu [1000,3000) %llu [3000,-) %llu\n",
           latency_hist_count(&hist, 0, 1000), latency_hist_count(&hist, 1000, 3000),
           latency_hist_count(&hist, 3000, -1));
}

/* Fill known samples, print figures and histograms, and check the error path. */
int main(void)
{
    static const long long samples[] = { -5, 0, 15, 999, 1000, 1500, 2500, 2999, 4200, 2000000 };

    latency_hist_reset(&hist);
    for (size_t i = 0; i < sizeof samples / sizeof samples[0]; i++)
        latency_hist_add(&hist, samples[i]);
    figures();
    printf("-- 1000 ns bins, 4 rows\n");
    latency_hist_print(&hist, 1000, 4, stdout);
    printf("-- 500 ns bins, 3 rows\n");
    latency_hist_print(&hist, 500, 3, stdout);
    printf("bad bin 15 -> %d\n", latency_hist_print(&hist, 15, 4, stdout));
    printf("bad rows 0 -> %d\n", latency_hist_print(&hist, 1000, 0, stdout));
    latency_hist_reset(&hist);
    latency_hist_add(&hist, 250);
    printf("-- one sample, 100 ns bins\n");
    latency_hist_print(&hist, 100, 10, stdout);
    return 0;
}
