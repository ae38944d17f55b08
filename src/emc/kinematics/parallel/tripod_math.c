/* tripod_math.c: three struts from fixed base points meet at the tool point. */
#include <math.h>
#include "parallel_math.h"

/* Base joints A=(0,0,0), B=(bx,0,0), C=(cx,cy,0). */
static void base_points(const tripod_geom_t *g, double c[3][3])
{
    const double pts[3][3] = {{0, 0, 0}, {g->bx, 0, 0}, {g->cx, g->cy, 0}};
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++)
            c[k][i] = pts[k][i];
}

/* Spheres of the strut lengths around the base joints; above the base unless below. */
int tripod_forward(const tripod_geom_t *g, const double *joints, EmcPose *pos, int below)
{
    double c[3][3];
    base_points(g, c);
    return trilaterate_pose(c, joints, !below, joints, pos);
}

/* Strut k is the distance from base joint k to the tool point. */
int tripod_inverse(const tripod_geom_t *g, const EmcPose *pos, double *joints)
{
    double c[3][3];
    if (!(fabs(g->bx) > 0.0) || !(fabs(g->cy) > 0.0))
        return -1;
    base_points(g, c);
    for (int k = 0; k < 3; k++)
        joints[k] = sqrt((pos->tran.x - c[k][0]) * (pos->tran.x - c[k][0])
                         + (pos->tran.y - c[k][1]) * (pos->tran.y - c[k][1])
                         + pos->tran.z * pos->tran.z);
    cart_pass_inverse(pos, joints, 3);
    return 0;
}
