/* rotate_math.c: XY plane of the joints turned 45 degrees against the world. */
#include <math.h>
#include "cartesian_math.h"

#define HALF_SQRT2 0.70710678118654752440

/* World XY is joint XY rotated by +45 degrees. */
void rotate_forward(const double *joints, EmcPose *pos)
{
    pos->tran.x = HALF_SQRT2 * (joints[0] - joints[1]);
    pos->tran.y = HALF_SQRT2 * (joints[0] + joints[1]);
    cart_pass_forward(joints, pos, 2);
}

/* Joint XY is world XY rotated by -45 degrees. */
void rotate_inverse(const EmcPose *pos, double *joints)
{
    joints[0] = HALF_SQRT2 * (pos->tran.x + pos->tran.y);
    joints[1] = HALF_SQRT2 * (pos->tran.y - pos->tran.x);
    cart_pass_inverse(pos, joints, 2);
}
