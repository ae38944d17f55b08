/* millturn_math.c: turning mode of a mill-turn: the lathe's Z runs along machine X, its X along machine Z. */
#include "millturn_math.h"

/* X = J2 (radial), Y = -J1 (keeps the frame right-handed), Z = J0 (along the turning spindle). */
void millturn_turn_forward(const double *joints, EmcPose *pos)
{
    pos->tran.x = joints[2];
    pos->tran.y = -joints[1];
    pos->tran.z = joints[0];
}

/* J0 = Z, J1 = -Y, J2 = X. */
void millturn_turn_inverse(const EmcPose *pos, double *joints)
{
    joints[0] = pos->tran.z;
    joints[1] = -pos->tran.y;
    joints[2] = pos->tran.x;
}
