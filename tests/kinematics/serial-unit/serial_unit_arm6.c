/* serial_unit_arm6.c: unit tests of the PUMA / 3-2-1 closed-form arm kinematics. */
#include <math.h>
#include <stdio.h>
#include "serial_unit.h"
#include "emc/kinematics/serial/arm6_math.h"
#include "emc/kinematics/serial/genser_math.h"

static const arm6_params_t puma560 = {0, 300, 50, 0, 0, 70, 400, 70};
static const arm6_params_t offset_arm = {75, 320, 40, 450, 30, -10, 350, 90};

/* The genser chain describing the same arm as p. */
static void genser_of_arm(const arm6_params_t *p, genser_params_t *g)
{
    genser_defaults(g);
    g->d[0] = p->d1;
    g->a[1] = p->a1;
    g->d[1] = p->d2;
    g->a[2] = p->a2;
    g->d[2] = p->d3;
    g->a[3] = p->a3;
    g->d[3] = p->d4;
    g->d[5] = p->d6;
}

/* Random joints away from the wrist singularity. */
static void random_joints(double *q)
{
    for (int i = 0; i < ARM6_JOINTS; i++)
        q[i] = su_random(-175, 175);
    if (fabs(q[4]) < 2)
        q[4] = 30;
}

/* Closed-form forward equals the DH chain product; every configuration round trips. */
static int arm_grid(const arm6_params_t *p, const char *label)
{
    genser_params_t g;
    genser_of_arm(p, &g);
    int trips = 0;
    for (int n = 0; n < 300; n++) {
        double q[ARM6_JOINTS], out[ARM6_JOINTS] = {0};
        EmcPose pos, chain, back;
        unsigned long flags;
        random_joints(q);
        arm6_forward(p, q, &pos, &flags);
        genser_forward(&g, q, &chain);
        su_check(su_pose_diff(&pos, &chain) < 1e-8, label);
        su_check(arm6_inverse(p, &pos, flags, out) == 0 && su_angle_diff(q, out, 6) < 1e-6, label);
        for (unsigned long f = 0; f < 8; f++) {
            if (arm6_inverse(p, &pos, f, out) < 0)
                continue;
            arm6_forward(p, out, &back, NULL);
            su_check(su_pose_diff(&pos, &back) < 1e-7, label);
            trips++;
        }
    }
    return trips;
}

/* Hand-computed poses of the PUMA 560 geometry. */
static void puma_known(void)
{
    double home[ARM6_JOINTS] = {0}, turned[ARM6_JOINTS] = {90, 0, 0, 0, 0, 0};
    double bent[ARM6_JOINTS] = {0, -90, 90, 0, 90, 0};
    EmcPose pos;
    unsigned long flags;
    su_print_pose("puma fwd home", arm6_forward(&puma560, home, &pos, &flags), &pos);
    printf("puma home flags: 0x%lx\n", flags);
    su_print_pose("puma fwd 90 0 0 0 0 0", arm6_forward(&puma560, turned, &pos, &flags), &pos);
    su_print_pose("puma fwd 0 -90 90 0 90 0", arm6_forward(&puma560, bent, &pos, &flags), &pos);
    printf("puma bent flags: 0x%lx\n", flags);
}

/* Unreachable and invalid poses are refused and leave the joints alone. */
static void puma_refused(void)
{
    double j[ARM6_JOINTS] = {1, 2, 3, 4, 5, 6};
    EmcPose far = {{2000, 0, 0}, 180, 0, 0, 0, 0, 0};
    su_print_joints("puma unreachable", arm6_inverse_nearest(&puma560, &far, j), j, 6);
    EmcPose inside = {{0, 0, 0}, 180, 0, 0, 0, 0, 0};
    su_print_joints("puma inside lateral offset", arm6_inverse_nearest(&puma560, &inside, j), j, 6);
    EmcPose bad = {{350, 70, INFINITY}, 180, 0, 0, 0, 0, 0};
    su_check(arm6_inverse_nearest(&puma560, &bad, j) != 0, "puma infinite pose refused");
    arm6_params_t flat = puma560;
    flat.a2 = 0;
    EmcPose home = {{350, 70, -470}, 180, 0, 0, 0, 0, 0};
    su_check(arm6_inverse(&flat, &home, 0, j) != 0, "puma A2 = 0 refused");
}

/* Wrist singularity keeps joint 3; nearest picks the current configuration and whole turns. */
static void puma_seeded(void)
{
    double q[ARM6_JOINTS] = {10, -40, 30, 25, 0, 15}, out[ARM6_JOINTS] = {0, 0, 0, 40, 0, 0};
    EmcPose pos, back;
    unsigned long flags;
    arm6_forward(&puma560, q, &pos, &flags);
    printf("puma singular flags: 0x%lx\n", flags);
    int rc = arm6_inverse(&puma560, &pos, flags, out);
    arm6_forward(&puma560, out, &back, NULL);
    su_print_joints("puma singular keeps j3", rc, out, 6);
    su_check(su_pose_diff(&pos, &back) < 1e-7, "puma singular round trip");
    double r[ARM6_JOINTS] = {-150, -120, 150, 170, -60, 350};
    double seed[ARM6_JOINTS] = {-149, -121, 151, 171, -59, 349};
    arm6_forward(&puma560, r, &pos, &flags);
    su_print_joints("puma nearest", arm6_inverse_nearest(&puma560, &pos, seed), seed, 6);
}

/* All PUMA / 3-2-1 checks. */
void su_arm6_tests(void)
{
    puma_known();
    printf("puma round trips: %d\n", arm_grid(&puma560, "puma grid"));
    printf("offset arm round trips: %d\n", arm_grid(&offset_arm, "offset arm grid"));
    puma_refused();
    puma_seeded();
}
