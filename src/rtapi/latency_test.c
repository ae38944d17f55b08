/* latency_test.c: latency-test: base and servo rtapi tasks, wake-up jitter statistics. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "latency_hist.h"
#include "rtapi.h"

typedef struct {
    const char *name;
    long long period_ns;
    int task_id;
    latency_hist_t hist;
    unsigned long long overruns;
} latency_thread_t;

static volatile int measuring;

/* Task body: record how late each wake-up is against its deadline. */
static void measure(void *arg)
{
    latency_thread_t *t = arg;

    for (;;) {
        long long deadline = rtapi_task_pll_get_reference();
        rtapi_wait();
        if (measuring)
            latency_hist_add(&t->hist, rtapi_get_time() - deadline);
    }
}

/* Parse a period: number with unit s/ms/us/µs/ns; bare numbers < 1000 are µs,
   larger ones ns. Returns ns, or -1 when malformed or not positive. */
static long long parse_period(const char *text)
{
    static const struct { const char *unit; double scale; } units[] = {
        { "s", 1e9 }, { "ms", 1e6 }, { "us", 1e3 }, { "\xc2\xb5s", 1e3 }, { "ns", 1 },
    };
    char *end;
    double value = strtod(text, &end);

    if (end == text || !(value > 0) || !isfinite(value))
        return -1;
    if (*end == '\0')
        return (long long)llround(value < 1000 ? value * 1e3 : value);
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (strcmp(end, units[i].unit) == 0)
            return (long long)llround(value * units[i].scale);
    return -1;
}

/* Start one measuring task; 0 or negative errno. */
static int start_thread(latency_thread_t *t, int prio)
{
    t->task_id = rtapi_task_new(measure, t, prio, 0, 0, 0);
    if (t->task_id < 0)
        return t->task_id;
    return rtapi_task_start(t->task_id, (unsigned long)t->period_ns);
}

/* Print one thread's figures as a text row. */
static void print_text_row(const latency_thread_t *t)
{
    const latency_hist_t *h = &t->hist;

    printf("%-6s %10lld %10llu %8lld %8lld %8lld %10lld %10lld %9llu\n", t->name,
           t->period_ns, h->samples, h->min_ns, latency_hist_percentile(h, 0.50),
           latency_hist_percentile(h, 0.99), latency_hist_percentile(h, 0.9999),
           h->max_ns, t->overruns);
}

/* Print one thread's figures as a JSON object. */
static void print_json_row(const latency_thread_t *t, int last)
{
    const latency_hist_t *h = &t->hist;

    printf("    {\"name\": \"%s\", \"period_ns\": %lld, \"samples\": %llu, \"min_ns\": %lld, "
           "\"p50_ns\": %lld, \"p99_ns\": %lld, \"p99_99_ns\": %lld, \"max_ns\": %lld, "
           "\"overruns\": %llu}%s\n", t->name, t->period_ns, h->samples, h->min_ns,
           latency_hist_percentile(h, 0.50), latency_hist_percentile(h, 0.99),
           latency_hist_percentile(h, 0.9999), h->max_ns, t->overruns, last ? "" : ",");
}

/* Print a text histogram per thread (latency-histogram). */
static void report_histograms(latency_thread_t *threads, int n, long long bin_ns)
{
    for (int i = 0; i < n; i++) {
        printf("\n%s thread (period %lld ns), wake-up jitter in %lld ns bins:\n",
               threads[i].name, threads[i].period_ns, bin_ns);
        latency_hist_print(&threads[i].hist, bin_ns, 40, stdout);
    }
}

/* Print the report for n threads. */
static void report(latency_thread_t *threads, int n, double seconds, int json)
{
    const char *type = rtapi_realtime_type_name(rtapi_get_realtime_type());

    if (json) {
        printf("{\n  \"duration_s\": %g,\n  \"realtime\": %s,\n  \"realtime_type\": \"%s\",\n"
               "  \"threads\": [\n", seconds, rtapi_is_realtime() ? "true" : "false", type);
        for (int i = 0; i < n; i++)
            print_json_row(&threads[i], i == n - 1);
        printf("  ]\n}\n");
        return;
    }
    printf("latency-test: %g s, %s (jitter = wake-up time minus deadline, ns)\n", seconds, type);
    printf("%-6s %10s %10s %8s %8s %8s %10s %10s %9s\n", "thread", "period", "samples", "min",
           "p50", "p99", "p99.99", "max", "overruns");
    for (int i = 0; i < n; i++)
        print_text_row(&threads[i]);
}

/* Print usage; returns the exit status to use. */
static int usage(FILE *out, int status)
{
    fprintf(out, "Usage: latency-test [-t SECONDS] [--json | --histogram[=BIN_NS]]"
            " [base_period [servo_period]]\n"
            "  one period: a single servo thread; none: base 25us, servo 1ms\n"
            "  periods: NUMBER[s|ms|us|ns]; a bare number < 1000 is us, else ns\n"
            "  --histogram: also print a text histogram per thread (bins of BIN_NS,\n"
            "  a multiple of 10, default 1000)\n");
    return status;
}

/* Parse -t SECONDS; -1 when malformed. */
static double parse_seconds(const char *text)
{
    char *end;
    double s = strtod(text, &end);

    return (end == text || *end || !(s > 0) || !isfinite(s)) ? -1 : s;
}

/* Parse the --histogram bin width: default 1000 ns; -1 when malformed. */
static long long parse_bin(const char *text)
{
    char *end;
    long long bin;

    if (!text)
        return 1000;
    bin = strtoll(text, &end, 10);
    return (end == text || *end || bin <= 0 || bin % LATENCY_BUCKET_NS) ? -1 : bin;
}

/* Give each thread up to 5 s more to record its first sample (loaded hosts). */
static void wait_for_samples(latency_thread_t *threads, int n)
{
    struct timespec tick = { 0, 10000000L };

    for (int i = 0; i < n; i++) {
        const unsigned long long *samples = &threads[i].hist.samples;
        for (int t = 0; t < 500 && __atomic_load_n(samples, __ATOMIC_ACQUIRE) == 0; t++)
            nanosleep(&tick, NULL);
    }
}

/* Run the threads for the given time, then stop them and collect overruns. */
static int run(latency_thread_t *threads, int n, double seconds)
{
    struct timespec ts = { (time_t)seconds, (long)((seconds - (time_t)seconds) * 1e9) };
    int prio = rtapi_prio_highest();

    for (int i = 0; i < n; i++) {
        int rc = start_thread(&threads[i], prio);
        if (rc < 0) {
            fprintf(stderr, "latency-test: cannot start the %s thread: %s\n",
                    threads[i].name, strerror(-rc));
            return 1;
        }
        prio = rtapi_prio_next_lower(prio);
    }
    measuring = 1;
    while (nanosleep(&ts, &ts) != 0)
        ;
    wait_for_samples(threads, n);
    measuring = 0;
    for (int i = 0; i < n; i++) {
        rtapi_task_stats_t st;
        if (rtapi_task_get_stats(threads[i].task_id, &st) == 0)
            threads[i].overruns = st.overruns;
        rtapi_task_delete(threads[i].task_id);
    }
    return 0;
}

/* Parse the command line, run the threads, print the report. */
int main(int argc, char **argv)
{
    static latency_thread_t threads[2] = { { "base", 25000, -1, { 0 }, 0 },
                                           { "servo", 1000000, -1, { 0 }, 0 } };
    static const struct option options[] = {
        { "json", no_argument, NULL, 'j' }, { "help", no_argument, NULL, 'h' },
        { "histogram", optional_argument, NULL, 'H' }, { 0 } };
    double seconds = 10;
    long long bin_ns = 0;
    int json = 0, opt, first = 0, n = 2;

    while ((opt = getopt_long(argc, argv, "t:h", options, NULL)) != -1) {
        if (opt == 't' && (seconds = parse_seconds(optarg)) < 0) {
            fprintf(stderr, "latency-test: -t %s: not a positive number of seconds\n", optarg);
            return 1;
        }
        if (opt == 'j')
            json = 1;
        if (opt == 'H' && (bin_ns = parse_bin(optarg)) < 0) {
            fprintf(stderr, "latency-test: --histogram=%s: not a positive multiple of %d ns\n",
                    optarg, LATENCY_BUCKET_NS);
            return 1;
        }
        if (opt == 'h' || opt == '?')
            return usage(opt == 'h' ? stdout : stderr, opt == 'h' ? 0 : 1);
    }
    if (argc - optind > 2)
        return usage(stderr, 1);
    if (argc - optind == 1)
        first = 1, n = 1;
    for (int i = first; i < 2 && optind < argc; i++, optind++) {
        threads[i].period_ns = parse_period(argv[optind]);
        if (threads[i].period_ns <= 0) {
            fprintf(stderr, "latency-test: '%s' is not a valid period\n", argv[optind]);
            return 1;
        }
    }
    if (run(threads + first, n, seconds) != 0)
        return 1;
    report(threads + first, n, seconds, json);
    if (bin_ns > 0 && !json)
        report_histograms(threads + first, n, bin_ns);
    return 0;
}
