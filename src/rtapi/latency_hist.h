/* latency_hist.h: fixed-size latency histogram (10 ns buckets to 1 ms) with percentiles. */
#ifndef LATENCY_HIST_H
#define LATENCY_HIST_H

#include <stdio.h>

#define LATENCY_BUCKET_NS 10
#define LATENCY_BUCKETS 100000

typedef struct {
    unsigned long long samples;
    long long min_ns;
    long long max_ns;
    unsigned long long overflow;          /* samples >= LATENCY_BUCKETS buckets */
    unsigned int counts[LATENCY_BUCKETS];
} latency_hist_t;

/* Empty the histogram. */
void latency_hist_reset(latency_hist_t *h);
/* Add one latency sample (negative values count as 0). */
void latency_hist_add(latency_hist_t *h, long long ns);
/* Smallest value v with at least fraction of the samples <= v (bucket resolution). */
long long latency_hist_percentile(const latency_hist_t *h, double fraction);
/* Count of samples in [from_ns, to_ns) at bucket resolution (to_ns < 0: no upper end). */
unsigned long long latency_hist_count(const latency_hist_t *h, long long from_ns, long long to_ns);
/* Print a text histogram with bins of bin_ns (a multiple of LATENCY_BUCKET_NS) and at most
   max_rows rows; the last row gathers everything above. Returns 0 or -EINVAL. */
int latency_hist_print(const latency_hist_t *h, long long bin_ns, int max_rows, FILE *out);

#endif
