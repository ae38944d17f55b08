/* limit3_unit.c: unit tests of limit3's follower: constraints, lock-on, no overshoot, bad limits. */
#include <math.h>
#include <stdio.h>
#include "hal/components/limit3_math.h"

#define PERIOD_S 0.001
#define TWO_PI 6.283185307179586

static int failures;

/* Print one check and count it when it failed. */
static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "ok" : "FAIL", what);
    if (!ok)
        failures++;
}

/* Worst violations seen while following a signal. */
typedef struct {
    double max_pos_over, max_vel, max_acc;
    int locked;          /* samples with out == in exactly */
    double max_err_late; /* largest |out - in| in the second half */
} follow_stats_t;

typedef double (*signal_fn)(double t_s);

/* Run the follower over a signal and collect the stats. */
static follow_stats_t follow(signal_fn sig, const limit3_limits_t *lim, int n)
{
    limit3_state_t st = {0, 0, 0};
    follow_stats_t fs = {0, 0, 0, 0, 0};
    double v_prev = 0;
    for (int i = 0; i < n; i++) {
        double x = sig(i * PERIOD_S);
        double before = st.pos;
        limit3_step(&st, lim, x, 0, PERIOD_S);
        double v = (st.pos - before) / PERIOD_S, a = (v - v_prev) / PERIOD_S;
        v_prev = v;
        fs.max_pos_over = fmax(fs.max_pos_over, fmax(st.pos - lim->pos_max, lim->pos_min - st.pos));
        fs.max_vel = fmax(fs.max_vel, fabs(v));
        fs.max_acc = fmax(fs.max_acc, fabs(a));
        fs.locked += st.pos == x;
        if (i >= n / 2)
            fs.max_err_late = fmax(fs.max_err_late, fabs(st.pos - x));
    }
    return fs;
}

static double sine(double t) { return 100 * sin(TWO_PI * 2 * t); }
static double square(double t) { return fmod(t, 1.0) < 0.5 ? 100 : -100; }
static double big_triangle(double t) { double f = fmod(t, 1.0); return f < 0.5 ? -300 + 1200 * f : 900 - 1200 * f; }
static double ramp(double t) { return 50 * t; }

/* The limits sit just above a 2 Hz, 100-unit sine: it must be followed exactly. */
static void sine_following(void)
{
    limit3_limits_t lim = {-101, 101, 1500, 15800, 2};
    follow_stats_t fs = follow(sine, &lim, 2000);
    check(fs.max_pos_over <= LIMIT3_EPS, "sine: position limits hold");
    check(fs.max_vel <= 1500 * (1 + 1e-9), "sine: velocity limit holds");
    check(fs.max_acc <= 15800 * (1 + 1e-6), "sine: acceleration limit holds");
    check(fs.max_err_late == 0, "sine: locked on the input after the start-up transient");
}

/* A square wave cannot be followed: limits hold and each plateau is reached exactly. */
static void square_following(void)
{
    limit3_limits_t lim = {-101, 101, 1500, 15800, 2};
    follow_stats_t fs = follow(square, &lim, 2000);
    check(fs.max_pos_over <= LIMIT3_EPS, "square: position limits hold");
    check(fs.max_vel <= 1500 * (1 + 1e-9), "square: velocity limit holds");
    check(fs.max_acc <= 15800 * (1 + 1e-6), "square: acceleration limit holds");
    check(fs.locked > 500, "square: each plateau is reached and held exactly");
}

/* An input that runs far past min and max: the output stops at them without overshoot. */
static void beyond_limits(void)
{
    limit3_limits_t lim = {-100, 100, 1000, 10000, 2};
    limit3_state_t st = {0, 0, 0};
    double top = -1e9, bottom = 1e9;
    int at_max = 0, at_min = 0;
    for (int i = 0; i < 3000; i++) {
        limit3_step(&st, &lim, big_triangle(i * PERIOD_S), 0, PERIOD_S);
        top = fmax(top, st.pos);
        bottom = fmin(bottom, st.pos);
        at_max += st.pos == 100;
        at_min += st.pos == -100;
    }
        check(fabs(top - 100) <= LIMIT3_EPS && fabs(bottom + 100) <= LIMIT3_EPS,
          "beyond limits: reaches max and min, never past them (within 1e-9)");
    check(at_max > 100 && at_min > 100, "beyond limits: rests on the limits while the input is past them");
}

/* A ramp: the output catches up and then moves with the input's velocity, exactly on it. */
static void ramp_matching(void)
{
    limit3_limits_t lim = {-1e20, 1e20, 1e20, 1000, 2};
    follow_stats_t fs = follow(ramp, &lim, 1000);
    check(fs.max_err_late == 0, "ramp: velocity matched and locked on");
    check(fs.max_acc <= 1000 * (1 + 1e-6), "ramp: acceleration limit holds while catching up");
}

/* load jumps to the clamped input; disable returns to zero; NaN input holds; zero maxa stays finite. */
static void special_inputs(void)
{
    limit3_limits_t lim = {-5, 5, 10000, 1e6, 2};
    limit3_state_t st = {0, 0, 0};
    limit3_step(&st, &lim, 20, 1, PERIOD_S);
    check(st.pos == 5, "load jumps to the input clamped to max");
    for (int i = 0; i < 3000; i++)
        limit3_step(&st, &lim, 0, 0, PERIOD_S);
    check(st.pos == 0, "target 0 (disabled) is reached exactly");
    for (int i = 0; i < 3000; i++)
        limit3_step(&st, &lim, 2, 0, PERIOD_S);
    limit3_step(&st, &lim, NAN, 0, PERIOD_S);
    check(st.pos == 2, "a NaN input holds the output");
    limit3_limits_t stuck = {-5, 5, 10, 0, 2};
    limit3_step(&st, &stuck, 3, 0, PERIOD_S);
    check(isfinite(st.pos), "maxa 0 gives a finite output");
    limit3_limits_t rough = {-1e20, 1e20, 1e20, 1000, 0};
    follow_stats_t fs = follow(ramp, &rough, 1000);
    check(fs.max_acc <= 1000 * (1 + 1e-6), "smooth-steps 0: acceleration limit still holds");
}

int main(void)
{
    sine_following();
    square_following();
    beyond_limits();
    ramp_matching();
    special_inputs();
    printf("%d failures\n", failures);
    return failures != 0;
}
