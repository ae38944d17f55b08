/* serial_unit_genser.c: unit tests of the general serial chain (DH forward, iterative inverse). */
#include <math.h>
#include <stdio.h>
#include "serial_unit.h"
#include "emc/kinematics/serial/genser_math.h"

/* Hand-computed poses of the default chain. */
static void genser_known(void)
{
    genser_params_t g;
    genser_defaults(&g);
    double home[GENSER_JOINTS] = {0}, q[GENSER_JOINTS] = {90, 0, 0, 0, 0, 0};
    EmcPose pos;
    su_print_pose("genser fwd home", genser_forward(&g, home, &pos), &pos);
    su_print_pose("genser fwd 90 0 0 0 0 0", genser_forward(&g, q, &pos), &pos);
    g.a[2] = 0;
    g.d[3] = 0;
    g.a[3] = 0;
    g.d[2] = 0;
    g.d[0] = 100;
    su_print_pose("genser fwd zero links, D-0 100", genser_forward(&g, home, &pos), &pos);
}

/* Inverse from a seed near an answer reaches the pose within the iteration cap. */
static int genser_grid(const genser_params_t *g, const char *label, unsigned int *worst)
{
    int trips = 0;
    for (int n = 0; n < 200; n++) {
        double q[GENSER_JOINTS], seed[GENSER_JOINTS];
        EmcPose pos, back;
        unsigned int used;
        for (int i = 0; i < GENSER_JOINTS; i++) {
            q[i] = su_random(-170, 170);
            seed[i] = q[i] + su_random(-10, 10);
        }
        if (fabs(q[4]) < 5)
            continue;
        genser_forward(g, q, &pos);
        int rc = genser_inverse(g, &pos, seed, &used);
        genser_forward(g, seed, &back);
        su_check(rc == 0 && su_pose_diff(&pos, &back) < 1e-7, label);
        su_check(used <= g->max_iterations, label);
        *worst = used > *worst ? used : *worst;
        trips++;
    }
    return trips;
}

/* unrotate: joint i is driven together with joint i-1. */
static void genser_unrotate(void)
{
    genser_params_t g, plain;
    genser_defaults(&g);
    genser_defaults(&plain);
    g.unrotate[5] = 1;
    double q[GENSER_JOINTS] = {5, -30, 40, 10, 50, 30}, adjusted[GENSER_JOINTS];
    for (int i = 0; i < GENSER_JOINTS; i++)
        adjusted[i] = q[i];
    adjusted[5] = q[5] - q[4];
    EmcPose a, b;
    genser_forward(&g, q, &a);
    genser_forward(&plain, adjusted, &b);
    su_check(su_pose_diff(&a, &b) < 1e-9, "unrotate forward");
    double seed[GENSER_JOINTS] = {0, -25, 35, 0, 45, 0};
    unsigned int used;
    int rc = genser_inverse(&g, &a, seed, &used);
    su_print_joints("genser unrotate inverse", rc, seed, GENSER_JOINTS);
}

/* Unreachable poses, a tiny iteration cap and NaN are refused; joints are left alone. */
static void genser_refused(void)
{
    genser_params_t g;
    genser_defaults(&g);
    double j[GENSER_JOINTS] = {1, 2, 3, 4, 5, 6};
    unsigned int used;
    EmcPose far = {{2000, 0, 0}, 180, 0, 0, 0, 0, 0};
    int rc = genser_inverse(&g, &far, j, &used);
    su_print_joints("genser unreachable", rc, j, GENSER_JOINTS);
    printf("genser unreachable iterations: %u\n", used);
    EmcPose near = {{300, 100, -450}, 170, 10, 20, 0, 0, 0};
    g.max_iterations = 1;
    rc = genser_inverse(&g, &near, j, &used);
    printf("genser max-iterations 1: rc=%d iterations=%u\n", rc, used);
    g.max_iterations = GENSER_DEFAULT_MAX_ITERATIONS;
    rc = genser_inverse(&g, &near, j, &used);
    printf("genser from 1..6 seed: rc=%d converged=%d\n", rc, used > 1 && used < 100);
    EmcPose bad = {{NAN, 0, 0}, 0, 0, 0, 0, 0, 0};
    su_check(genser_inverse(&g, &bad, j, &used) != 0, "genser NaN refused");
}

/* All general-chain checks. */
void su_genser_tests(void)
{
    genser_params_t g;
    unsigned int worst = 0;
    genser_defaults(&g);
    genser_known();
    printf("genser round trips: %d\n", genser_grid(&g, "genser grid", &worst));
    g.a[0] = 25;
    g.alpha[0] = 0.3;
    g.d[5] = 120;
    g.d[4] = 15;
    printf("genser skewed chain round trips: %d\n", genser_grid(&g, "genser skewed", &worst));
    printf("genser worst iterations below 30: %d\n", worst < 30);
    genser_unrotate();
    genser_refused();
}
