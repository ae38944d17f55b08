/* tp_bench.c: planner figures: tp-bench's metrics offline, segments per CPU second, CPU per servo cycle. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "tpb.h"

#define HIST_BINS 100000            /* 0.1 us bins up to 10 ms */

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

/* One table row per generated program, and the geometric mean of time over bound. */
static int programs(double jerk)
{
    tpb_machine_t mc = bench_machine(jerk);
    double logsum = 0.0;
    int n = 0, bad = 0;
    printf("%-20s %8s %7s %6s %7s %7s %7s %9s %9s %9s %6s\n", "program", "cycles", "feed%", "t/bnd",
           "v/lim", "a/lim", "j/lim", "viol v/a/j", "dev mm", "miss mm", "over");
    for (int k = 0; tpb_names[k]; k++) {
        tpb_program_t p;
        tpb_trace_t tr = {0, 0, NULL, NULL};
        tpb_result_t r;
        tpb_make(&p, tpb_names[k]);
        int em = tpb_run(&p, &mc, 2000, &tr, NULL, NULL, 0, NULL);
        tpb_measure(&p, &mc, &tr, &r);
        double tb = r.cycles * mc.period / r.pass_bound;
        printf("%-20s %8ld %7.1f %6.2f %7.3f %7.3f %7.3f %3ld/%ld/%ld %9.5f %9.5f %3ld/%ld%s\n", p.name, r.cycles,
               100.0 * r.feed_bound / (r.cycles * mc.period), tb, r.vel_ratio, r.acc_ratio, r.jerk_ratio,
               r.vel_viol, r.acc_viol, r.jerk_viol, r.max_dev, r.max_miss, r.dev_viol, r.miss_viol,
               em ? " (emergency brakes)" : "");
        logsum += log(tb);
        n++;
        bad += r.vel_viol + r.acc_viol + r.jerk_viol + r.dev_viol + r.miss_viol + em != 0;
        tpb_free(&p);
        free(tr.p);
    }
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
    tpb_run_split(&p, &mc, 2000, NULL, NULL, NULL, 0, &cycles, &add_cpu, &cycle_cpu);
    printf("library %s: %d segments planned in %.2f s CPU: %.0f segments per CPU second; "
           "%ld servo cycles executing them: %.2f us each on average\n",
           jerk > 0 ? "S-curve" : "trapezoid", segments, add_cpu, segments / add_cpu, cycles,
           1e6 * cycle_cpu / cycles);
    tpb_free(&p);
}

/* Per-cycle CPU time (adds and run_cycle together) on a long program: percentiles and maximum. */
static void cycle_cpu(int segments, double jerk)
{
    tpb_machine_t mc = bench_machine(jerk);
    tpb_program_t p;
    double *hist = calloc(HIST_BINS, sizeof(double)), mx = 0.0, total = 0.0;
    tpb_make_long(&p, segments);
    long cycles;
    tpb_run(&p, &mc, 2000, NULL, &mx, hist, HIST_BINS, &cycles);
    for (int b = 0; b < HIST_BINS; b++)
        total += hist[b];
    double q[3] = {0.5, 0.9999, 1.0}, acc = 0.0, out[3] = {0, 0, 0};
    int qi = 0;
    for (int b = 0; b < HIST_BINS && qi < 3; b++) {
        acc += hist[b];
        while (qi < 3 && acc >= q[qi] * total) {
            out[qi] = (b + 1) / 10.0;
            qi++;
        }
    }
    printf("planner CPU per servo cycle (%s, %d segments, %ld cycles, up to %d adds per cycle): "
           "median %.1f us, p99.99 %.1f us, max %.1f us\n",
           jerk > 0 ? "S-curve" : "trapezoid", segments, cycles, TPB_ADDS_PER_CYCLE, out[0], out[1], mx);
    free(hist);
    tpb_free(&p);
}

int main(int argc, char **argv)
{
    double jerk = 0.0;
    const char *what = argc > 1 ? argv[1] : "all";
    for (int k = 2; k + 1 < argc; k++)
        if (!strcmp(argv[k], "--jerk"))
            jerk = atof(argv[k + 1]);
    if (!strcmp(what, "programs"))
        return programs(jerk) ? 1 : 0;
    if (!strcmp(what, "throughput")) {
        throughput(150000, jerk);
        return 0;
    }
    if (!strcmp(what, "cycle-cpu")) {
        cycle_cpu(150000, jerk);
        return 0;
    }
    fprintf(stderr, "usage: tp_bench programs|throughput|cycle-cpu [--jerk J]\n");
    return 2;
}
