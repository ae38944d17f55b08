/* genhex_unit.c: unit tests of genhex_math: hand-computed lengths, round trips, refused poses. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "emc/kinematics/hexapod/genhex_math.h"

static int failures;

/* Print one check and count it when it failed. */
static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "ok" : "FAIL", what);
    if (!ok)
        failures++;
}

/* A pose from six numbers (U V W zero). */
static EmcPose pose6(double x, double y, double z, double a, double b, double c)
{
    EmcPose p;
    memset(&p, 0, sizeof(p));
    p.tran = (PmCartesian){x, y, z};
    p.a = a; p.b = b; p.c = c;
    return p;
}

/* Largest difference over the six pose coordinates. */
static double pose_diff(const EmcPose *p, const EmcPose *q)
{
    double d[6] = {p->tran.x - q->tran.x, p->tran.y - q->tran.y, p->tran.z - q->tran.z,
                   p->a - q->a, p->b - q->b, p->c - q->c};
    double m = 0;
    for (int i = 0; i < 6; i++)
        m = fmax(m, fabs(d[i]));
    return m;
}

/* Level platform at height h: every strut is sqrt(h^2 + horizontal distance^2). */
static void known_lengths(void)
{
    genhex_geom_t g;
    double len[GENHEX_STRUTS];
    genhex_default_geometry(&g);
    EmcPose p = pose6(0, 0, 20, 0, 0, 0);
    int ok = genhex_inverse(&g, &p, len, NULL) == 0;
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        double dx = g.platform[i].x - g.base[i].x, dy = g.platform[i].y - g.base[i].y;
        ok = ok && fabs(len[i] - sqrt(400.0 + dx * dx + dy * dy)) < 1e-12;
    }
    check(ok, "level pose at z=20 gives the hand-computed strut lengths");
    printf("strut 0 at z=20: %.6f (expected %.6f)\n", len[0], sqrt(400.0 + 21.95 * 21.95 + 1.75 * 1.75));
    p = pose6(0, 0, 20, 0, 0, 90);
    genhex_inverse(&g, &p, len, NULL);
    check(fabs(len[0] - sqrt(400.0 + pow(-11.5 + 22.95, 2) + pow(-1.0 - 13.25, 2))) < 1e-9,
          "c=90 turns platform joint 0 to (-11.5, -1)");
    double m[3][3];
    genhex_rotation(0, 90, 0, m);
    check(fabs(m[0][2] - 1) < 1e-12 && fabs(m[2][0] + 1) < 1e-12, "b=90 maps platform Z to world X");
}

/* Tool and spindle offsets rise every base and platform joint: nothing changes level, and tilted the
 * controlled point moves along the platform Z (the offset joints equal a shifted origin). */
static void tool_offset(void)
{
    genhex_geom_t g;
    double a[GENHEX_STRUTS], b[GENHEX_STRUTS], rot[3][3];
    genhex_default_geometry(&g);
    EmcPose p = pose6(1, 2, 20, 0, 0, 0);
    genhex_inverse(&g, &p, a, NULL);
    g.z_offset = 5;
    genhex_inverse(&g, &p, b, NULL);
    int same = 1;
    for (int i = 0; i < GENHEX_STRUTS; i++)
        same = same && fabs(a[i] - b[i]) < 1e-12;
    check(same, "an offset changes no strut while the platform is level");
    p = pose6(1, 2, 20, 10, -5, 0);
    genhex_inverse(&g, &p, b, NULL);
    genhex_rotation(10, -5, 0, rot);
    g.z_offset = 0;
    EmcPose moved = pose6(1 + 5 * rot[0][2], 2 + 5 * rot[1][2], 20 + 5 * rot[2][2] - 5, 10, -5, 0);
    genhex_inverse(&g, &moved, a, NULL);
    same = 1;
    for (int i = 0; i < GENHEX_STRUTS; i++)
        same = same && fabs(a[i] - b[i]) < 1e-9;
    check(same, "tilted, an offset of 5 moves the controlled point 5 along the platform Z");
}

/* forward(inverse(p)) == p over a grid of poses, from a level guess. */
static void round_trips(double screw_lead)
{
    genhex_geom_t g;
    double len[GENHEX_STRUTS], worst = 0;
    int count = 0, failed = 0;
    genhex_default_geometry(&g);
    g.screw_lead = screw_lead;
    for (double x = -4; x <= 4; x += 4)
        for (double y = -4; y <= 4; y += 4)
            for (double z = 15; z <= 30; z += 7.5)
                for (double ang = -10; ang <= 10; ang += 10) {
                    EmcPose p = pose6(x, y, z, ang, -ang / 2, ang * 1.5), q = pose6(0, 0, 20, 0, 0, 0);
                    genhex_solve_t s = {1e-9, 500, 120, 0};
                    count++;
                    if (genhex_inverse(&g, &p, len, NULL) < 0 || genhex_forward(&g, len, &q, &s) < 0) {
                        failed++;
                        continue;
                    }
                    worst = fmax(worst, pose_diff(&p, &q));
                }
    printf("screw lead %g: %d poses, %d failed, worst error %s 1e-8\n", screw_lead, count, failed,
           worst < 1e-8 ? "below" : "ABOVE");
    check(failed == 0 && worst < 1e-8, "forward(inverse(p)) == p over the grid");
}

/* The twist correction changes lengths only when a lead is set, by lead * angle / 2pi. */
static void twist(void)
{
    genhex_geom_t g;
    double plain[GENHEX_STRUTS], corr[GENHEX_STRUTS];
    genhex_default_geometry(&g);
    for (int i = 0; i < GENHEX_STRUTS; i++)
        g.base_n[i] = (PmCartesian){1, 0, 0};
    for (int i = 0; i < GENHEX_STRUTS; i++)
        g.platform_n[i] = (PmCartesian){0, 0, 1};
    EmcPose p = pose6(0, 0, 20, 0, 0, 0);
    genhex_inverse(&g, &p, plain, NULL);
    g.screw_lead = 2.0;
    genhex_inverse(&g, &p, corr, NULL);
    check(fabs(plain[1] - corr[1]) > 1e-6 && fabs(plain[1] - corr[1]) <= 0.5 + 1e-12,
          "screw lead 2 changes a twisted strut by at most a quarter turn of lead");
    double reported[GENHEX_STRUTS];
    genhex_inverse(&g, &p, corr, reported);
    check(fabs(corr[1] - plain[1] - reported[1]) < 1e-12, "the correction is reported per strut");
}

/* Unreachable lengths, a flat platform and an iteration cap all fail without touching the pose. */
static void refused(void)
{
    genhex_geom_t g;
    double len[GENHEX_STRUTS] = {10, 10, 10, 10, 10, 10};
    genhex_default_geometry(&g);
    EmcPose q = pose6(0, 0, 20, 0, 0, 0), keep = q;
    genhex_solve_t s = {1e-9, 500, 120, 0};
    int r = genhex_forward(&g, len, &q, &s);
    check(r < 0 && pose_diff(&q, &keep) == 0, "struts shorter than the base gap have no pose");
    EmcPose flat = pose6(0, 0, 0, 0, 0, 0), high = pose6(0, 0, 20, 0, 0, 0);
    genhex_inverse(&g, &high, len, NULL);
    q = high;
    check(genhex_forward(&g, len, &q, &s) == 0 && s.iterations == 1 && pose_diff(&q, &high) < 1e-12,
          "an exact guess converges in the first step");
    genhex_inverse(&g, &high, len, NULL);
    q = flat;
    r = genhex_forward(&g, len, &q, &s);
    check(r == GENHEX_RUNAWAY && pose_diff(&q, &flat) == 0,
          "a guess in the base plane (no Z gradient) is refused (-2)");
    EmcPose p = pose6(3, -2, 25, 5, 5, 5);
    genhex_inverse(&g, &p, len, NULL);
    q = pose6(0, 0, 20, 0, 0, 0);
    s.limit_iterations = 1;
    r = genhex_forward(&g, len, &q, &s);
    check(r == GENHEX_NO_CONVERGENCE, "limit-iterations 1 stops the solver (-5)");
    q = pose6(0, 0, 20, 0, 0, 0);
    s.limit_iterations = 5000;
    s.conv_criterion = -1;
    r = genhex_forward(&g, len, &q, &s);
    check(r == GENHEX_NO_CONVERGENCE && s.iterations == GENHEX_MAX_ITERATIONS + 1,
          "limit-iterations 5000 still stops after 1000 steps (bounded cycle time)");
    s.conv_criterion = 1e-9;
    q = pose6(0, 0, 20, 0, 0, 0);
    s.limit_iterations = 120;
    s.max_error = 0.5;
    r = genhex_forward(&g, len, &q, &s);
    check(r == GENHEX_RUNAWAY, "a summed strut error over max-error 0.5 is refused (-2)");
    s.max_error = 500;
    q = pose6(0, 0, 20, 0, 0, 0);
    r = genhex_forward(&g, len, &q, &s);
    check(r == 0 && pose_diff(&p, &q) < 1e-8, "the same solve converges with max-error 500");
    double zero[GENHEX_STRUTS] = {20, 20, 0, 20, 20, 20};
    check(genhex_forward(&g, zero, &q, &s) == GENHEX_DEGENERATE, "a strut of length 0 is refused (-1)");
    g.platform[0] = g.base[0];
    check(genhex_inverse(&g, &flat, len, NULL) == GENHEX_DEGENERATE, "a zero-length strut is refused");
}

/* Run every group; the exit status reports failures. */
int main(void)
{
    known_lengths();
    tool_offset();
    round_trips(0.0);
    round_trips(1.5);
    twist();
    refused();
    printf("%d failures\n", failures);
    return failures != 0;
}
