/* tp_bench.c: planner figures: tp-bench's metrics offline, segments per CPU second, CPU per servo cycle. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "tpb.h"


/* tp-bench's machine: 1 kHz, 500 mm/s, 5000 mm/s^2 on every axis; jerk 0 = trapezoid. */
static tpb_machine_t bench_machine(double jerk)
{
    tpb_machine_t mc;
    for (int i = 0; i < 3; i++) {
        mc.vel[i] = 500.0;
        mc.acc[i] = 5000.0;
    }
    mc.jerk = jerk;
    mc.vtraj = 500.0;
    mc.atraj = 5000.0;
    mc.period = 0.001;
    return mc;
}

/* Run one program (G64 Q chains merged first, as canon does) and print its table row; adds log(time/bound) to *logsum.  Non-zero when a
 * limit, the tolerance or a safe continuation was broken. */
static int program_row(const tpb_program_t *p, const tpb_machine_t *mc, double *logsum)
{
    tpb_trace_t tr = {0, 0, NULL, NULL};
    tpb_result_t r;
    tpb_program_t merged;               /* what canon sends: G64 Q chains merged into lines */
    tpb_naive_merge(p, &merged);
    int em = tpb_run(&merged, mc, 2000, &tr, NULL, 0, NULL);
    tpb_free(&merged);
    tpb_measure(p, mc, &tr, &r);
    double tb = r.cycles * mc->period / r.pass_bound;
    const char *name = strrchr(p->name, '/') ? strrchr(p->name, '/') + 1 : p->name;
    printf("%-20.20s %8ld %7.1f %6.2f %7.3f %7.3f %7.3f %3ld/%ld/%ld %9.5f %9.5f %3ld/%ld%s\n", name, r.cycles,
           100.0 * r.feed_bound / (r.cycles * mc->period), tb, r.vel_ratio, r.acc_ratio, r.jerk_ratio,
           r.vel_viol, r.acc_viol, r.jerk_viol, r.max_dev, r.max_miss, r.dev_viol, r.miss_viol,
           em ? " (emergency brakes)" : "");
    *logsum += log(tb);
    free(tr.p);
    return r.vel_viol + r.acc_viol + r.jerk_viol + r.dev_viol + r.miss_viol + em != 0;
}

/* One table row per program (the generated ones, or canonical-call files), and the geometric
 * mean of time over bound. */
static int programs(double jerk, char **files, int nfiles)
{
    tpb_machine_t mc = bench_machine(jerk);
    double logsum = 0.0;
    int n = 0, bad = 0;
    printf("%-20s %8s %7s %6s %7s %7s %7s %9s %9s %9s %6s\n", "program", "cycles", "feed%", "t/bnd",
           "v/lim", "a/lim", "j/lim", "viol v/a/j", "dev mm", "miss mm", "over");
    for (int k = 0; nfiles ? k < nfiles : tpb_names[k] != NULL; k++) {
        tpb_program_t p;
        if (nfiles ? tpb_load_canon(&p, files[k]) : tpb_make(&p, tpb_names[k])) {
            fprintf(stderr, "tp_bench: %s: no moves read\n", nfiles ? files[k] : tpb_names[k]);
            bad++;
            continue;
        }
        bad += program_row(&p, &mc, &logsum);
        n++;
        tpb_free(&p);
    }
    if (n)
        printf("geometric mean time/bound: %.3f\n", exp(logsum / n));
    return bad;
}

/* Segments planned per CPU second on a long program (adding them: geometry, blends, caps,
 * regions), and the CPU of the servo cycles that execute them, on the same run. */
static void throughput(int segments, double jerk)
{
    tpb_machine_t mc = bench_machine(jerk);
    tpb_program_t p;
    tpb_make_long(&p, segments);
    long cycles;
    double add_cpu = 0.0, cycle_cpu = 0.0;
    tpb_run_split(&p, &mc, 2000, NULL, NULL, 0, &cycles, &add_cpu, &cycle_cpu);
    printf("library %s: %d segments planned in %.2f s CPU: %.0f segments per CPU second; "
           "%ld servo cycles executing them: %.2f us each on average\n",
           jerk > 0 ? "S-curve" : "trapezoid", segments, add_cpu, segments / add_cpu, cycles,
           1e6 * cycle_cpu / cycles);
    tpb_free(&p);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Median, p99.99 and maximum of n values (sorted in place). */
static void quantiles(double *v, long n, double *med, double *p9999, double *mx)
{
    qsort(v, (size_t)n, sizeof(*v), cmp_double);
    *med = v[n / 2];
    *p9999 = v[(long)(0.9999 * (n - 1))];
    *mx = v[n - 1];
}

/* Per-cycle CPU time (adds and run_cycle together) on a long program.  The run is deterministic,
 * so it is repeated: the first run's figures include whatever else the machine did, the minimum
 * over the runs of each cycle's time is the planner's own cost. */
static void cycle_cpu(int segments, double jerk)
{
    enum { RUNS = 3 };
    tpb_machine_t mc = bench_machine(jerk);
    tpb_program_t p;
    long cap = 4L * segments + 100000, cycles = 0;
    double *first = calloc((size_t)cap, sizeof(double)), *run = calloc((size_t)cap, sizeof(double));
    double *low = calloc((size_t)cap, sizeof(double));
    tpb_make_long(&p, segments);
    for (int r = 0; r < RUNS; r++) {
        tpb_run(&p, &mc, 2000, NULL, run, cap, &cycles);
        cycles = cycles < cap ? cycles : cap;
        for (long k = 0; k < cycles; k++)
            low[k] = r ? fmin(low[k], run[k]) : run[k];
        if (!r)
            memcpy(first, run, (size_t)cycles * sizeof(double));
    }
    double m1, q1, x1, m2, q2, x2;
    quantiles(first, cycles, &m1, &q1, &x1);
    quantiles(low, cycles, &m2, &q2, &x2);
    printf("planner CPU per servo cycle (%s, %d segments, %ld cycles, up to %d adds per cycle): "
           "one run: median %.1f us, p99.99 %.1f us, max %.1f us; least of %d runs per cycle: "
           "median %.1f us, p99.99 %.1f us, max %.1f us\n",
           jerk > 0 ? "S-curve" : "trapezoid", segments, cycles, TPB_ADDS_PER_CYCLE, m1, q1, x1, RUNS,
           m2, q2, x2);
    free(first);
    free(run);
    free(low);
    tpb_free(&p);
}

/* Print every servo sample of one program (generated name or canon file): x y z speed. */
static int trace(const char *name, double jerk)
{
    tpb_machine_t mc = bench_machine(jerk);
    tpb_program_t p, merged;
    if (strchr(name, '/') || strchr(name, '.') ? tpb_load_canon(&p, name) : tpb_make(&p, name)) {
        fprintf(stderr, "tp_bench: %s: no moves read\n", name);
        return 1;
    }
    tpb_naive_merge(&p, &merged);
    tpb_trace_t tr = {0, 0, NULL, NULL};
    tpb_run(&merged, &mc, 2000, &tr, NULL, 0, NULL);
    for (int k = 0; k < tr.n; k++) {
        const double *q = tr.p[k], *prev = k ? tr.p[k - 1] : p.start;
        double v = sqrt((q[0] - prev[0]) * (q[0] - prev[0]) + (q[1] - prev[1]) * (q[1] - prev[1]) +
                        (q[2] - prev[2]) * (q[2] - prev[2])) / mc.period;
        printf("%.6f %.6f %.6f %.4f\n", q[0], q[1], q[2], v);
    }
    free(tr.p);
    tpb_free(&p);
    tpb_free(&merged);
    return 0;
}

int main(int argc, char **argv)
{
    double jerk = 0.0;
    const char *what = argc > 1 ? argv[1] : "all";
    char *files[64];
    int nfiles = 0;
    for (int k = 2; k < argc; k++) {
        if (!strcmp(argv[k], "--jerk") && k + 1 < argc)
            jerk = atof(argv[++k]);
        else if (nfiles < 64)
            files[nfiles++] = argv[k];
    }
    if (!strcmp(what, "programs"))
        return programs(jerk, NULL, 0) ? 1 : 0;
    if (!strcmp(what, "canon") && nfiles > 0)
        return programs(jerk, files, nfiles) ? 1 : 0;
    if (!strcmp(what, "trace") && nfiles == 1)
        return trace(files[0], jerk);
    if (!strcmp(what, "throughput")) {
        throughput(150000, jerk);
        return 0;
    }
    if (!strcmp(what, "cycle-cpu")) {
        cycle_cpu(150000, jerk);
        return 0;
    }
    fprintf(stderr, "usage: tp_bench programs|throughput|cycle-cpu [--jerk J]\n"
                    "       tp_bench canon FILE... [--jerk J]   (files of rs274 -g output)\n"
                    "       tp_bench trace NAME|FILE [--jerk J] (x y z speed per servo cycle)\n");
    return 2;
}
