/* lineardelta_math.c: linear delta (three vertical towers, carriages with parallel rods). */
#include <math.h>
#include "parallel_math.h"

#define SIN_60 0.86602540378443864676

/* Tower k (0 at +Y, 1 at front left, 2 at front right) in the XY plane. */
static void tower(const lineardelta_geom_t *g, int k, double *tx, double *ty)
{
    static const double dir[3][2] = {{0.0, 1.0}, {-SIN_60, -0.5}, {SIN_60, -0.5}};
    *tx = dir[k][0] * g->r;
    *ty = dir[k][1] * g->r;
}

/* Rods meet below the carriages: the lower meeting point of three spheres. */
int lineardelta_forward(const lineardelta_geom_t *g, const double *joints, EmcPose *pos)
{
    double c[3][3], rad[3];
    for (int k = 0; k < 3; k++) {
        tower(g, k, &c[k][0], &c[k][1]);
        c[k][2] = joints[k];
        rad[k] = g->l;
    }
    return trilaterate_pose(c, rad, 0, joints, pos);
}

/* Each carriage sits the rod's vertical extent above the effector. */
int lineardelta_inverse(const lineardelta_geom_t *g, const EmcPose *pos, double *joints)
{
    double h[3];
    for (int k = 0; k < 3; k++) {
        double tx, ty;
        tower(g, k, &tx, &ty);
        double dx = tx - pos->tran.x, dy = ty - pos->tran.y;
        double v2 = g->l * g->l - dx * dx - dy * dy;
        if (!(v2 >= 0.0))
            return -1;
        h[k] = pos->tran.z + sqrt(v2);
    }
    for (int k = 0; k < 3; k++)
        joints[k] = h[k];
    cart_pass_inverse(pos, joints, 3);
    return 0;
}
