/* kins_unit.c: unit tests of the kinematics helpers: coordinates parsing, identity map, ops check. */
#include <stdio.h>
#include <string.h>
#include "emc/kinematics/kins_coords.h"

/* Parse one coordinates string and print the map or the error. */
static void parse(const char *text)
{
    kins_coords_t c;
    char why[160];
    int rc = kins_coords_parse(text, &c, why, sizeof(why));
    printf("parse '%s': %d", text ? text : "(null)", rc);
    if (rc < 0) {
        printf(" %s\n", why);
        return;
    }
    for (int j = 0; j < c.joint_count; j++)
        printf(" j%d=%c", j, kins_axis_letter(c.axis_of_joint[j]));
    printf("\n");
}

/* Round trip through the identity map of a gantry. */
static void identity(void)
{
    kins_coords_t c;
    char why[160];
    EmcPose p = {{1, 2, 3}, 4, 5, 6, 7, 8, 9};
    double j[KINS_MAX_JOINTS] = {0};
    kins_coords_parse("XYYZC", &c, why, sizeof(why));
    kins_identity_inverse(&c, &p, j);
    printf("inverse XYYZC: %g %g %g %g %g\n", j[0], j[1], j[2], j[3], j[4]);
    EmcPose q = {{-1, -1, -1}, -1, -1, -1, -1, -1, -1};
    j[2] = 99;
    kins_identity_forward(&c, j, &q);
    printf("forward: x=%g y=%g z=%g a=%g b=%g c=%g u=%g\n", q.tran.x, q.tran.y, q.tran.z,
           q.a, q.b, q.c, q.u);
    printf("joint of axis Y=%d W=%d\n", kins_coords_joint_of_axis(&c, 1),
           kins_coords_joint_of_axis(&c, 8));
}

/* Dummy entries for a table under test. */
static KINEMATICS_TYPE t(void) { return KINEMATICS_BOTH; }
static int f(const double *j, EmcPose *p, const KINEMATICS_FORWARD_FLAGS *a,
             KINEMATICS_INVERSE_FLAGS *b) { (void)j; (void)p; (void)a; (void)b; return 0; }
static int i(const EmcPose *p, double *j, const KINEMATICS_INVERSE_FLAGS *a,
             KINEMATICS_FORWARD_FLAGS *b) { (void)j; (void)p; (void)a; (void)b; return 0; }
static int s(void) { return 0; }
static int w(int n) { return n; }

/* A matching table passes; version, size and empty entries are refused. */
static void ops_check(void)
{
    char why[200];
    kins_ops_t ops = {KINS_OPS_VERSION, sizeof(kins_ops_t), "demo", t, f, i, s, w};
    printf("good: %d\n", kins_ops_check(&ops, why, sizeof(why)));
    ops.version = 7;
    printf("version: %d %s\n", kins_ops_check(&ops, why, sizeof(why)), why);
    ops.version = KINS_OPS_VERSION;
    ops.size = 8;
    printf("size: %d %s\n", kins_ops_check(&ops, why, sizeof(why)), why);
    ops.size = sizeof(kins_ops_t);
    ops.inverse = NULL;
    printf("empty: %d %s\n", kins_ops_check(&ops, why, sizeof(why)), why);
    printf("none: %d %s\n", kins_ops_check(NULL, why, sizeof(why)), why);
}

int main(void)
{
    parse(NULL);
    parse("");
    parse("xyz");
    parse(" X y\tZ  a ");
    parse("xyyz");
    parse("xq");
    parse("   ");
    parse("XYZABCUVWXYZABCUVW");
    printf("letters: %d %d %d %d %c %c\n", kins_axis_index('w'), kins_axis_index('C'),
           kins_axis_index('?'), kins_axis_index(0), kins_axis_letter(4), kins_axis_letter(12));
    identity();
    ops_check();
    return 0;
}
