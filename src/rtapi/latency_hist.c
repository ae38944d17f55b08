/* latency_hist.c: latency histogram used by latency-test. */
#include <errno.h>
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

/* Sum the buckets covering [from_ns, to_ns); overflow samples count when to_ns < 0. */
unsigned long long latency_hist_count(const latency_hist_t *h, long long from_ns, long long to_ns)
{
    long long first = from_ns / LATENCY_BUCKET_NS;
    long long last = to_ns < 0 ? LATENCY_BUCKETS : to_ns / LATENCY_BUCKET_NS;
    unsigned long long sum = to_ns < 0 ? h->overflow : 0;

    if (last > LATENCY_BUCKETS)
        last = LATENCY_BUCKETS;
    for (long long i = first < 0 ? 0 : first; i < last; i++)
        sum += h->counts[i];
    return sum;
}

/* Number of rows needed to reach the maximum sample, capped at max_rows. */
static int hist_rows(const latency_hist_t *h, long long bin_ns, int max_rows)
{
    long long rows = h->max_ns / bin_ns + 1;

    return rows > max_rows ? max_rows : (int)rows;
}

/* One row: range, count and a bar scaled so the fullest row is 50 characters. */
static void hist_row(FILE *out, long long from, long long to, unsigned long long n,
                     unsigned long long peak)
{
    char range[48];
    int bar = peak ? (int)((n * 50 + peak - 1) / peak) : 0;

    if (to < 0)
        snprintf(range, sizeof range, ">= %lld", from);
    else
        snprintf(range, sizeof range, "%lld-%lld", from, to - 1);
    fprintf(out, "%21s ns %10llu %.*s\n", range, n, bar,
            "##################################################");
}

/* Print the histogram rows of one thread. */
int latency_hist_print(const latency_hist_t *h, long long bin_ns, int max_rows, FILE *out)
{
    unsigned long long peak = 0;
    int rows;

    if (bin_ns <= 0 || bin_ns % LATENCY_BUCKET_NS || max_rows < 1)
        return -EINVAL;
    rows = hist_rows(h, bin_ns, max_rows);
    for (int r = 0; r < rows; r++) {
        long long to = r == rows - 1 ? -1 : (r + 1) * bin_ns;
        unsigned long long n = latency_hist_count(h, r * bin_ns, to);
        peak = n > peak ? n : peak;
    }
    for (int r = 0; r < rows; r++) {
        long long to = r == rows - 1 ? -1 : (r + 1) * bin_ns;
        hist_row(out, r * bin_ns, to, latency_hist_count(h, r * bin_ns, to), peak);
    }
    return 0;
}
