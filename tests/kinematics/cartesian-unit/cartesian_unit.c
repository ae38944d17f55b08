/* cartesian_unit.c: unit tests of the cartesian kinematics math: hand-computed poses, round trips. */
#include <math.h>
#include <stdio.h>
#include "emc/kinematics/cartesian/cartesian_math.h"

/* Largest difference tolerated by a round trip. */
#define TOL 1e-9

/* Print a pose with six decimals. */
static void print_pose(const char *tag, int rc, const EmcPose *p)
{
    printf("%s %d: X=%.6f Y=%.6f Z=%.6f A=%.6f B=%.6f C=%.6f U=%.6f V=%.6f W=%.6f\n", tag, rc,
           p->tran.x, p->tran.y, p->tran.z, p->a, p->b, p->c, p->u, p->v, p->w);
}

/* Print the first n joints. */
static void print_joints(const char *tag, int rc, const double *j, int n)
{
    printf("%s %d:", tag, rc);
    for (int k = 0; k < n; k++)
        printf(" j%d=%.6f", k, j[k]);
    printf("\n");
}

/* Largest axis difference between two poses. */
static double pose_diff(const EmcPose *a, const EmcPose *b)
{
    double d[9] = {a->tran.x - b->tran.x, a->tran.y - b->tran.y, a->tran.z - b->tran.z,
                   a->a - b->a, a->b - b->b, a->c - b->c, a->u - b->u, a->v - b->v,
                   a->w - b->w};
    double m = 0.0;
    for (int k = 0; k < 9; k++)
        m = fmax(m, fabs(d[k]));
    return m;
}

/* A grid pose number n (x, y, z spread over +-300, other axes distinct). */
static EmcPose grid_pose(int n)
{
    EmcPose p = {{-300.0 + 60.0 * (n % 11), -300.0 + 60.0 * ((n / 11) % 11),
                  -300.0 + 60.0 * (n / 121)}, 1.5, -2.5, 3.5, 4.5, -5.5, 6.5};
    return p;
}

/* Round trip forward(inverse(p)) over the 11^3 grid for the two plain maps. */
static void roundtrip_plain(const char *name, void (*fwd)(const double *, EmcPose *),
                            void (*inv)(const EmcPose *, double *))
{
    int bad = 0;
    for (int n = 0; n < 1331; n++) {
        EmcPose p = grid_pose(n), q = {{0, 0, 0}, 0, 0, 0, 0, 0, 0};
        double j[9];
        inv(&p, j);
        fwd(j, &q);
        bad += pose_diff(&p, &q) > TOL;
    }
    printf("%s round trip: 1331 poses, %d wrong\n", name, bad);
}

/* CoreXY and rotated XY by hand, then round trips. */
static void plain_maps(void)
{
    double j[9] = {3, 1, 7, 10, 20, 30, 40, 50, 60};
    EmcPose p;
    corexy_forward(j, &p);
    print_pose("corexy fwd 3 1 7..", 0, &p);
    corexy_inverse(&p, j);
    print_joints("corexy inv", 0, j, 9);
    double r[9] = {1, 0, 2, 0, 0, 0, 0, 0, 0};
    rotate_forward(r, &p);
    print_pose("rotate fwd 1 0 2", 0, &p);
    EmcPose y = {{0, 1, 0}, 0, 0, 0, 0, 0, 0};
    rotate_inverse(&y, r);
    print_joints("rotate inv Y=1", 0, r, 3);
    roundtrip_plain("corexy", corexy_forward, corexy_inverse);
    roundtrip_plain("rotate", rotate_forward, rotate_inverse);
}

/* Shear/scale matrix by hand, round trip, singular matrix refused. */
static void matrix_map(void)
{
    matrix3_t m = {{{1, 0.5, 0}, {0, 1, 0}, {0, 0, 2}}};
    EmcPose p = {{1, 2, 3}, 4, 5, 6, 7, 8, 9}, q;
    double j[9];
    matrix_inverse_kins(&m, &p, j);
    print_joints("matrix inv 1 2 3", 0, j, 9);
    int rc = matrix_forward_kins(&m, j, &q);
    print_pose("matrix fwd", rc, &q);
    matrix3_t skew = {{{1.001, 0.002, -0.003}, {0.004, 0.998, 0.001}, {-0.002, 0.003, 1.0}}};
    int bad = 0;
    for (int n = 0; n < 1331; n++) {
        EmcPose g = grid_pose(n), back;
        matrix_inverse_kins(&skew, &g, j);
        bad += matrix_forward_kins(&skew, j, &back) != 0 || pose_diff(&g, &back) > TOL;
    }
    printf("matrix round trip: 1331 poses, %d wrong\n", bad);
    matrix3_t flat = {{{1, 2, 3}, {2, 4, 6}, {0, 0, 1}}};
    EmcPose keep = {{-1, -1, -1}, 0, 0, 0, 0, 0, 0};
    rc = matrix_forward_kins(&flat, j, &keep);
    printf("singular matrix: %d, pose untouched X=%g\n", rc, keep.tran.x);
}

/* Scorbot poses by hand, round trips (wrist in front of the shoulder), far points refused. */
static void scorbot(void)
{
    const scorbot_dims_t *d = &scorbot_er3_dims;
    double cases[3][9] = {{0, 0, 0, 1, 2, 3, 4, 5, 6}, {90, 0, 0}, {0, 90, -90}};
    EmcPose p;
    for (int c = 0; c < 3; c++) {
        scorbot_forward(d, cases[c], &p);
        print_pose("scorbot fwd", 0, &p);
    }
    double j[9];
    int rc = scorbot_inverse(d, &p, j);
    print_joints("scorbot inv", rc, j, 3);
    int bad = 0, tried = 0;
    for (int b = -150; b <= 150; b += 30)
        for (int s = -30; s <= 120; s += 15)
            for (int e = -165; e <= -15; e += 15) {
                double jj[9] = {b, s, e, 1, 2, 3, 4, 5, 6}, back[9];
                EmcPose w, w2;
                if (cos(s * M_PI / 180) + cos((s + e) * M_PI / 180) <= 0.0)
                    continue;
                scorbot_forward(d, jj, &w);
                tried++;
                if (scorbot_inverse(d, &w, back) != 0) {
                    bad++;
                    continue;
                }
                scorbot_forward(d, back, &w2);
                bad += pose_diff(&w, &w2) > TOL || fabs(back[2] - e) > 1e-6;
            }
    printf("scorbot round trip: %d poses, %d wrong\n", tried, bad);
    EmcPose far = {{1000, 0, 340}, 0, 0, 0, 0, 0, 0};
    double keep[3] = {-7, -7, -7};
    rc = scorbot_inverse(d, &far, keep);
    printf("scorbot out of reach: %d, joints untouched %g\n", rc, keep[0]);
}

/* Run every group. */
int main(void)
{
    plain_maps();
    matrix_map();
    scorbot();
    return 0;
}
