/* unit_util.h: printing and comparison helpers shared by the parallel kinematics unit tests. */
#ifndef UNIT_UTIL_H
#define UNIT_UTIL_H

#include <math.h>
#include <stdio.h>
#include "emc/kinematics/parallel/parallel_math.h"

/* Largest difference tolerated by a round trip. */
#define TOL 1e-9

/* v with values that round to zero printed without a sign. */
static inline double clean(double v)
{
    return fabs(v) < 5e-7 ? 0.0 : v;
}

/* Print the XYZ part of a pose (plus A B) with six decimals. */
static inline void print_pose(const char *tag, int rc, const EmcPose *p)
{
    printf("%s %d: X=%.6f Y=%.6f Z=%.6f A=%.6f B=%.6f\n", tag, rc, clean(p->tran.x),
           clean(p->tran.y), clean(p->tran.z), clean(p->a), clean(p->b));
}

/* Print the first n joints. */
static inline void print_joints(const char *tag, int rc, const double *j, int n)
{
    printf("%s %d:", tag, rc);
    for (int k = 0; k < n; k++)
        printf(" j%d=%.6f", k, clean(j[k]));
    printf("\n");
}

/* Largest axis difference between two poses (all nine axes). */
static inline double pose_diff(const EmcPose *a, const EmcPose *b)
{
    double d[9] = {a->tran.x - b->tran.x, a->tran.y - b->tran.y, a->tran.z - b->tran.z,
                   a->a - b->a, a->b - b->b, a->c - b->c, a->u - b->u, a->v - b->v,
                   a->w - b->w};
    double m = 0.0;
    for (int k = 0; k < 9; k++)
        m = fmax(m, fabs(d[k]));
    return m;
}

/* Pentapod tests (penta_unit.c). */
void penta_tests(void);

#endif
