/* serial_unit.c: unit tests of rotation helpers and SCARA math, and the test runner. */
#include <math.h>
#include <stdio.h>
#include "serial_unit.h"
#include "emc/kinematics/serial/serial_rot.h"
#include "emc/kinematics/serial/scara_math.h"

static int checks, failures;
static unsigned long long su_seed = 12345;

/* Count a check; print the label when it fails. */
void su_check(int ok, const char *label)
{
    checks++;
    if (!ok) {
        failures++;
        printf("FAIL: %s\n", label);
    }
}

/* A value for printing: tiny magnitudes become +0. */
static double su_clean(double v)
{
    return fabs(v) < 5e-7 ? 0.0 : v;
}

/* Print a pose. */
void su_print_pose(const char *label, int rc, const EmcPose *p)
{
    printf("%s: rc=%d X=%.6f Y=%.6f Z=%.6f A=%.6f B=%.6f C=%.6f\n", label, rc,
           su_clean(p->tran.x), su_clean(p->tran.y), su_clean(p->tran.z),
           su_clean(p->a), su_clean(p->b), su_clean(p->c));
}

/* Print joints. */
void su_print_joints(const char *label, int rc, const double *j, int n)
{
    printf("%s: rc=%d", label, rc);
    for (int i = 0; i < n; i++)
        printf(" j%d=%.6f", i, su_clean(j[i]));
    printf("\n");
}

/* Difference of two angles in degrees, modulo 360. */
static double su_angle(double x, double y)
{
    return fabs(serial_angle_near(x - y, 0.0));
}

/* Largest pose difference. */
double su_pose_diff(const EmcPose *x, const EmcPose *y)
{
    double d = fabs(x->tran.x - y->tran.x);
    d = fmax(d, fabs(x->tran.y - y->tran.y));
    d = fmax(d, fabs(x->tran.z - y->tran.z));
    d = fmax(d, su_angle(x->a, y->a));
    d = fmax(d, su_angle(x->b, y->b));
    return fmax(d, su_angle(x->c, y->c));
}

/* Largest joint difference modulo 360. */
double su_angle_diff(const double *x, const double *y, int n)
{
    double d = 0;
    for (int i = 0; i < n; i++)
        d = fmax(d, su_angle(x[i], y[i]));
    return d;
}

/* Linear congruential generator: same sequence on every run. */
double su_random(double lo, double hi)
{
    su_seed = su_seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(su_seed >> 11) / 9007199254740992.0;
}

/* Roll/pitch/yaw survive a trip through the matrix, including at pitch +-90. */
static void rpy_tests(void)
{
    static const double cases[][3] = {
        {0, 0, 0}, {10, 20, 30}, {-170, 45, 120}, {90, -89, -45}, {179, 1, -179},
    };
    for (unsigned i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        serial_mat3_t r;
        double a, b, c;
        serial_rot_from_rpy(cases[i][0], cases[i][1], cases[i][2], r);
        serial_rot_to_rpy(r, &a, &b, &c);
        su_check(su_angle(a, cases[i][0]) < 1e-9 && su_angle(b, cases[i][1]) < 1e-9 &&
                 su_angle(c, cases[i][2]) < 1e-9, "rpy round trip");
    }
    serial_mat3_t r;
    double a, b, c;
    serial_rot_from_rpy(30, 90, 50, r);
    serial_rot_to_rpy(r, &a, &b, &c);
    printf("rpy at pitch 90: A=%.6f B=%.6f C=%.6f\n", a, b, c);
    printf("angle near: %.1f %.1f %.1f\n", serial_angle_near(-10, 350),
           serial_angle_near(350, 0), serial_angle_near(190, -170));
}

/* SCARA: hand-computed poses, both elbows round trip, unreachable refused. */
static void scara_tests(void)
{
    scara_params_t p = {490, 340, 50, 250, 50, 50};
    double j[SCARA_JOINTS] = {0}, k[SCARA_JOINTS] = {90, 0, 10, 0, 5, 6};
    EmcPose pos;
    su_print_pose("scara fwd 0 0 0 0", scara_forward(&p, j, &pos, NULL), &pos);
    su_print_pose("scara fwd 90 0 10 0 5 6", scara_forward(&p, k, &pos, NULL), &pos);
    double l[SCARA_JOINTS] = {30, 90, 0, 0, 0, 0};
    su_print_pose("scara fwd 30 90 0 0", scara_forward(&p, l, &pos, NULL), &pos);
    int trips = 0;
    for (int n = 0; n < 200; n++) {
        double q[SCARA_JOINTS] = {su_random(-170, 170), su_random(-160, 160), su_random(-100, 100),
                                  su_random(-170, 170), su_random(-9, 9), su_random(-9, 9)};
        if (fabs(q[1]) < 1)
            continue;
        unsigned long flags;
        double out[SCARA_JOINTS] = {0};
        scara_forward(&p, q, &pos, &flags);
        int rc = scara_inverse(&p, &pos, flags, out);
        su_check(rc == 0 && su_angle_diff(q, out, SCARA_JOINTS) < 1e-7, "scara round trip");
        trips++;
    }
    printf("scara round trips: %d\n", trips);
    EmcPose far = {{700, 0, 0}, 0, 0, 0, 0, 0, 0};
    double keep[SCARA_JOINTS] = {1, 2, 3, 4, 5, 6};
    su_print_joints("scara unreachable", scara_inverse_keep_elbow(&p, &far, keep), keep, 6);
    EmcPose at = {{300, 200, 400}, 0, 0, 15, 0, 0, 0};
    double up[SCARA_JOINTS] = {0, 20, 0, 0, 0, 0}, down[SCARA_JOINTS] = {0, -20, 0, 0, 0, 0};
    su_print_joints("scara keep elbow +", scara_inverse_keep_elbow(&p, &at, up), up, 6);
    su_print_joints("scara keep elbow -", scara_inverse_keep_elbow(&p, &at, down), down, 6);
    EmcPose bad = {{NAN, 0, 0}, 0, 0, 0, 0, 0, 0};
    su_check(scara_inverse(&p, &bad, 0, keep) != 0, "scara NaN refused");
}

/* Run every group and print the totals. */
int main(void)
{
    rpy_tests();
    scara_tests();
    su_arm6_tests();
    su_genser_tests();
    su_three21_tests();
    printf("checks: %d failures: %d\n", checks, failures);
    return failures != 0;
}
