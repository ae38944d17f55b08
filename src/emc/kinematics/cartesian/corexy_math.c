/* corexy_math.c: CoreXY belt kinematics (two motors move X and Y together). */
#include "cartesian_math.h"

/* X is the mean of the motors, Y half their difference. */
void corexy_forward(const double *joints, EmcPose *pos)
{
    pos->tran.x = 0.5 * (joints[0] + joints[1]);
    pos->tran.y = 0.5 * (joints[0] - joints[1]);
    cart_pass_forward(joints, pos, 2);
}

/* Motor 0 turns for X+Y, motor 1 for X-Y. */
void corexy_inverse(const EmcPose *pos, double *joints)
{
    joints[0] = pos->tran.x + pos->tran.y;
    joints[1] = pos->tran.x - pos->tran.y;
    cart_pass_inverse(pos, joints, 2);
}
