/* passthrough.c: joints that drive one world axis each, shared by the cartesian modules. */
#include "cartesian_math.h"

/* Pointer to axis 0..8 of a pose in X Y Z A B C U V W order. */
static double *axis_ref(EmcPose *pos, int axis)
{
    double *refs[9] = {&pos->tran.x, &pos->tran.y, &pos->tran.z, &pos->a, &pos->b,
                       &pos->c, &pos->u, &pos->v, &pos->w};
    return refs[axis];
}

/* Copy joints first..8 into the pose axes first..8. */
void cart_pass_forward(const double *joints, EmcPose *pos, int first)
{
    for (int a = first; a < 9; a++)
        *axis_ref(pos, a) = joints[a];
}

/* Copy pose axes first..8 into joints first..8. */
void cart_pass_inverse(const EmcPose *pos, double *joints, int first)
{
    for (int a = first; a < 9; a++)
        joints[a] = *axis_ref((EmcPose *)pos, a);
}
