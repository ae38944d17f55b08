/* parallel_unit.c: unit tests of the delta, tripod and rose kinematics math. */
#include "unit_util.h"

/* A pose with XY on a grid of step over +-span, Z given, other axes distinct. */
static EmcPose grid_xy(int n, double span, double z)
{
    EmcPose p = {{-span + span / 5.0 * (n % 11), -span + span / 5.0 * (n / 11), z},
                 1.5, -2.5, 3.5, 4.5, -5.5, 6.5};
    return p;
}

/* Linear delta: centred effector by hand, a grid of round trips, out-of-reach refused. */
static void lineardelta(void)
{
    lineardelta_geom_t g = {269.0, 130.25};
    EmcPose p = {{0, 0, 0}, 0, 0, 0, 0, 0, 0}, q;
    double j[9] = {0}, keep[3] = {-7, -7, -7};
    int rc = lineardelta_inverse(&g, &p, j);
    print_joints("lineardelta inv 0 0 0", rc, j, 3);
    printf("  expected sqrt(269^2-130.25^2) = %.6f\n", sqrt(269.0 * 269.0 - 130.25 * 130.25));
    rc = lineardelta_forward(&g, j, &q);
    print_pose("lineardelta fwd", rc, &q);
    int bad = 0;
    for (int n = 0; n < 121; n++)
        for (int z = -100; z <= 100; z += 50) {
            EmcPose a = grid_xy(n, 80.0, z), b = {{0, 0, 0}, 0, 0, 0, 0, 0, 0};
            bad += lineardelta_inverse(&g, &a, j) != 0 || lineardelta_forward(&g, j, &b) != 0
                   || pose_diff(&a, &b) > TOL;
        }
    printf("lineardelta round trip: 605 poses, %d wrong\n", bad);
    EmcPose far = {{400, 0, 0}, 0, 0, 0, 0, 0, 0};
    printf("lineardelta out of reach: %d, joints untouched %g\n",
           lineardelta_inverse(&g, &far, keep), keep[0]);
    double apart[3] = {0, 0, 1000};
    printf("lineardelta rods cannot meet: %d\n", lineardelta_forward(&g, apart, &q));
}

/* Rotary delta: thighs straight down by hand, round trips, out-of-reach refused. */
static void rotarydelta(void)
{
    rotarydelta_geom_t g = {10.0, 10.0, 14.0, 2.0};
    double down[9] = {90, 90, 90}, j[9], keep[3] = {-7, -7, -7};
    EmcPose p = {{0, 0, 0}, 0, 0, 0, 0, 0, 0};
    int rc = rotarydelta_forward(&g, down, &p);
    print_pose("rotarydelta fwd 90 90 90", rc, &p);
    printf("  expected Z = -10 - sqrt(14^2-8^2) = %.6f\n", -10.0 - sqrt(196.0 - 64.0));
    rc = rotarydelta_inverse(&g, &p, j);
    print_joints("rotarydelta inv", rc, j, 3);
    int bad = 0;
    for (int n = 0; n < 121; n++)
        for (int z = -20; z <= -12; z += 2) {
            EmcPose a = grid_xy(n, 3.0, z), b = {{0, 0, 0}, 0, 0, 0, 0, 0, 0};
            bad += rotarydelta_inverse(&g, &a, j) != 0 || rotarydelta_forward(&g, j, &b) != 0
                   || pose_diff(&a, &b) > TOL;
        }
    printf("rotarydelta round trip: 605 poses, %d wrong\n", bad);
    EmcPose far = {{0, 0, -40}, 0, 0, 0, 0, 0, 0};
    printf("rotarydelta out of reach: %d, joints untouched %g\n",
           rotarydelta_inverse(&g, &far, keep), keep[0]);
}

/* Tripod: a point by hand, both z solutions, round trips, impossible struts refused. */
static void tripod(void)
{
    tripod_geom_t g = {1.0, 1.0, 1.0};
    EmcPose p = {{0, 0, 1}, 0, 0, 0, 0, 0, 0}, q;
    double j[9];
    int rc = tripod_inverse(&g, &p, j);
    print_joints("tripod inv 0 0 1", rc, j, 3);
    rc = tripod_forward(&g, j, &q, 0);
    print_pose("tripod fwd above", rc, &q);
    rc = tripod_forward(&g, j, &q, 1);
    print_pose("tripod fwd below", rc, &q);
    tripod_geom_t wide = {10.0, 3.0, 8.0};
    int bad = 0;
    for (int n = 0; n < 121; n++)
        for (int z = 1; z <= 9; z += 2) {
            EmcPose a = grid_xy(n, 10.0, z), b = {{0, 0, 0}, 0, 0, 0, 0, 0, 0};
            EmcPose under = a, c = b;
            under.tran.z = -z;
            bad += tripod_inverse(&wide, &a, j) != 0 || tripod_forward(&wide, j, &b, 0) != 0
                   || pose_diff(&a, &b) > TOL;
            bad += tripod_inverse(&wide, &under, j) != 0
                   || tripod_forward(&wide, j, &c, 1) != 0 || pose_diff(&under, &c) > TOL;
        }
    printf("tripod round trip: 1210 poses, %d wrong\n", bad);
    double short_struts[3] = {0.1, 0.1, 0.1};
    printf("tripod struts too short: %d\n", tripod_forward(&g, short_struts, &q, 0));
    tripod_geom_t line = {1.0, 2.0, 0.0};
    printf("tripod collinear base: %d %d\n", tripod_forward(&line, j, &q, 0),
           tripod_inverse(&line, &p, j));
}

/* Rose: polar map by hand, the rotary joint continuing past +-180 over several turns. */
static void rose(void)
{
    rose_state_t s = {0, 0, 0};
    double j[9] = {10, 5, 90};
    EmcPose p;
    rose_forward(&s, j, &p);
    print_pose("rose fwd r=10 z=5 90deg", 0, &p);
    EmcPose q = {{-3, -3, 1}, 0, 0, 0, 0, 0, 0};
    rose_inverse(&s, &q, j);
    print_joints("rose inv -3 -3 1", 0, j, 3);
    printf("  turns %g theta %g bigtheta %g\n", s.revolutions, s.theta_degrees, s.bigtheta_degrees);
    rose_state_t t = {0, 0, 0};
    int bad = 0;
    double offset = 0.0;
    for (int step = 0; step <= 1000; step++) {
        double deg = -700.0 + 1.4 * step;
        EmcPose a = {{20 * cos(deg * M_PI / 180), 20 * sin(deg * M_PI / 180), 2}, 0, 0, 0, 0, 0, 0};
        rose_inverse(&t, &a, j);
        if (step == 0)
            offset = j[2] - deg;
        bad += fabs(j[2] - deg - offset) > 1e-6 || fabs(j[0] - 20.0) > TOL;
    }
    printf("rose sweep -700..700 deg: offset %.6f, ends at %.6f (%g turns), %d wrong\n",
           offset, j[2], t.revolutions, bad);
    double at[9] = {20, 0, 725};
    rose_forward(&t, at, &p);
    EmcPose near = {{20 * cos(10 * M_PI / 180), 20 * sin(10 * M_PI / 180), 0}, 0, 0, 0, 0, 0, 0};
    rose_inverse(&t, &near, j);
    printf("rose forward at 725 then 10 deg: joint %.6f\n", j[2]);
    EmcPose centre = {{0, 0, 3}, 0, 0, 0, 0, 0, 0};
    rose_inverse(&t, &centre, j);
    printf("rose centre keeps the angle: r=%.6f joint %.6f\n", j[0], j[2]);
}

/* Run every group. */
int main(void)
{
    lineardelta();
    rotarydelta();
    tripod();
    rose();
    penta_tests();
    return 0;
}
