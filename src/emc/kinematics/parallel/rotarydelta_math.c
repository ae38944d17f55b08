/* rotarydelta_math.c: rotary delta (three motors turn thighs; shins reach the effector). */
#include <math.h>
#include "parallel_math.h"

#define DEG (M_PI / 180.0)

/* Arm k's direction, 0/120/240 degrees from +X. */
static void arm_dir(int k, double *cx, double *sy)
{
    *cx = cos(k * 120.0 * DEG);
    *sy = sin(k * 120.0 * DEG);
}

/* Shins meet below the knees: spheres around knee minus the effector offset. */
int rotarydelta_forward(const rotarydelta_geom_t *g, const double *joints, EmcPose *pos)
{
    double c[3][3], rad[3];
    for (int k = 0; k < 3; k++) {
        double cx, sy, th = joints[k] * DEG;
        arm_dir(k, &cx, &sy);
        double reach = g->platform_radius - g->effector_radius + g->thigh_length * cos(th);
        c[k][0] = reach * cx;
        c[k][1] = reach * sy;
        c[k][2] = -g->thigh_length * sin(th);
        rad[k] = g->shin_length;
    }
    return trilaterate_pose(c, rad, 0, joints, pos);
}

/* Thigh angle of one arm for the effector point in that arm's frame (knee outward). */
static int arm_angle(const rotarydelta_geom_t *g, double x, double y, double z, double *deg)
{
    double tl = g->thigh_length;
    double a = x + g->effector_radius - g->platform_radius;
    double e = -2.0 * a * tl, f = 2.0 * z * tl;
    double k = g->shin_length * g->shin_length - y * y - a * a - z * z - tl * tl;
    double rho = hypot(e, f);
    if (!(rho > 0.0) || !(fabs(k) <= rho))
        return -1;
    double th = atan2(f, e) + acos(k / rho);
    *deg = remainder(th / DEG, 360.0);
    return 0;
}

/* Turn the effector into each arm's frame and solve its angle. */
int rotarydelta_inverse(const rotarydelta_geom_t *g, const EmcPose *pos, double *joints)
{
    double th[3];
    for (int k = 0; k < 3; k++) {
        double cx, sy;
        arm_dir(k, &cx, &sy);
        double x = pos->tran.x * cx + pos->tran.y * sy;
        double y = -pos->tran.x * sy + pos->tran.y * cx;
        if (arm_angle(g, x, y, pos->tran.z, &th[k]) < 0)
            return -1;
    }
    for (int k = 0; k < 3; k++)
        joints[k] = th[k];
    cart_pass_inverse(pos, joints, 3);
    return 0;
}
