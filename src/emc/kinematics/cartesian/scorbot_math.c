/* scorbot_math.c: Scorbot ER-3 arm: base turn, shoulder and elbow place the wrist centre. */
#include <math.h>
#include "cartesian_math.h"

#define DEG (M_PI / 180.0)

const scorbot_dims_t scorbot_er3_dims = {16.0, 340.0, 221.0, 221.0};

/* Shoulder angle from horizontal, elbow relative to the upper arm, both up-positive. */
void scorbot_forward(const scorbot_dims_t *d, const double *joints, EmcPose *pos)
{
    double base = joints[0] * DEG, shoulder = joints[1] * DEG;
    double forearm = shoulder + joints[2] * DEG;
    double reach = d->l0_horizontal + d->l1_length * cos(shoulder) + d->l2_length * cos(forearm);
    pos->tran.x = reach * cos(base);
    pos->tran.y = reach * sin(base);
    pos->tran.z = d->l0_vertical + d->l1_length * sin(shoulder) + d->l2_length * sin(forearm);
    cart_pass_forward(joints, pos, 3);
}

/* Base faces the point, then a two-link planar solution with the elbow above the line. */
int scorbot_inverse(const scorbot_dims_t *d, const EmcPose *pos, double *joints)
{
    double base = atan2(pos->tran.y, pos->tran.x);
    double r = hypot(pos->tran.x, pos->tran.y) - d->l0_horizontal;
    double h = pos->tran.z - d->l0_vertical;
    double l1 = d->l1_length, l2 = d->l2_length;
    double c2 = (r * r + h * h - l1 * l1 - l2 * l2) / (2.0 * l1 * l2);
    if (!(c2 >= -1.0 && c2 <= 1.0))
        return -1;
    double elbow = -acos(c2);
    double shoulder = atan2(h, r) - atan2(l2 * sin(elbow), l1 + l2 * cos(elbow));
    joints[0] = base / DEG;
    joints[1] = shoulder / DEG;
    joints[2] = elbow / DEG;
    cart_pass_inverse(pos, joints, 3);
    return 0;
}
