/* trilaterate.c: the point three spheres share, used by the delta and tripod forward maps. */
#include <math.h>
#include "parallel_math.h"

/* Smallest centre spacing treated as distinct. */
#define TRI_EPS 1e-12

/* a - b. */
static void sub3(const double *a, const double *b, double *out)
{
    for (int i = 0; i < 3; i++)
        out[i] = a[i] - b[i];
}

/* a . b. */
static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Scale v to unit length; -1 when it is (near) zero. */
static int unit3(double *v)
{
    double n = sqrt(dot3(v, v));
    if (!(n > TRI_EPS))
        return -1;
    for (int i = 0; i < 3; i++)
        v[i] /= n;
    return 0;
}

/* Frame ex (c0->c1), ey (towards c2), ez = ex x ey; spacing d and c2's coordinates i, j. */
static int sphere_frame(const double c[3][3], double e[3][3], double *d, double *i, double *j)
{
    double c2[3];
    sub3(c[1], c[0], e[0]);
    *d = sqrt(dot3(e[0], e[0]));
    if (unit3(e[0]) < 0)
        return -1;
    sub3(c[2], c[0], c2);
    *i = dot3(e[0], c2);
    for (int k = 0; k < 3; k++)
        e[1][k] = c2[k] - *i * e[0][k];
    if (unit3(e[1]) < 0)
        return -1;
    *j = dot3(e[1], c2);
    e[2][0] = e[0][1] * e[1][2] - e[0][2] * e[1][1];
    e[2][1] = e[0][2] * e[1][0] - e[0][0] * e[1][2];
    e[2][2] = e[0][0] * e[1][1] - e[0][1] * e[1][0];
    return 0;
}

/* Intersect the spheres; pick the solution with the larger (upper) or smaller world z. */
int trilaterate(const double centre[3][3], const double radius[3], int upper, double out[3])
{
    double e[3][3], d, i, j;
    if (sphere_frame(centre, e, &d, &i, &j) < 0)
        return -1;
    double r0 = radius[0] * radius[0];
    double x = (r0 - radius[1] * radius[1] + d * d) / (2.0 * d);
    double y = (r0 - radius[2] * radius[2] + i * i + j * j) / (2.0 * j) - i / j * x;
    double z2 = r0 - x * x - y * y;
    if (!(z2 >= 0.0))
        return -1;
    double z = sqrt(z2);
    if ((e[2][2] < 0.0) == (upper != 0))
        z = -z;
    for (int k = 0; k < 3; k++)
        out[k] = centre[0][k] + x * e[0][k] + y * e[1][k] + z * e[2][k];
    return 0;
}

/* Forward map of a three-strut machine: XYZ where the spheres meet, joints 3.. pass through. */
int trilaterate_pose(const double centre[3][3], const double radius[3], int upper,
                     const double *joints, EmcPose *pos)
{
    double p[3];
    if (trilaterate(centre, radius, upper, p) < 0)
        return -1;
    pos->tran.x = p[0];
    pos->tran.y = p[1];
    pos->tran.z = p[2];
    cart_pass_forward(joints, pos, 3);
    return 0;
}
