/* latency_hist.c: latency histogram used by latency-test. */
#include <string.h>
#include "latency_hist.h"

/* Clear all counts. */
void latency_hist_reset(latency_hist_t *h)
{
    memset(h, 0, sizeof *h);
}

/* Count one sample. */
void latency_hist_add(latency_hist_t *h, long long ns)
{
    long long bucket;

    if (ns < 0)
        ns = 0;
    if (h->samples == 0 || ns < h->min_ns)
        h->min_ns = ns;
    if (h->samples == 0 || ns > h->max_ns)
        h->max_ns = ns;
    h->samples++;
    bucket = ns / LATENCY_BUCKET_NS;
    if (bucket >= LATENCY_BUCKETS)
        h->overflow++;
    else
        h->counts[bucket]++;
}

/* Walk the buckets up to the wanted fraction. */
long long latency_hist_percentile(const latency_hist_t *h, double fraction)
{
    unsigned long long need, seen = 0;
    long long value;

    if (h->samples == 0)
        return 0;
    need = (unsigned long long)(fraction * (double)h->samples);
    if (need < 1)
        need = 1;
    for (long i = 0; i < LATENCY_BUCKETS; i++) {
        seen += h->counts[i];
        if (seen >= need) {
            value = (long long)(i + 1) * LATENCY_BUCKET_NS - 1;
            if (value > h->max_ns)
                value = h->max_ns;
            return value < h->min_ns ? h->min_ns : value;
        }
    }
    return h->max_ns;
}
