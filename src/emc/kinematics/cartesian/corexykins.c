/* corexykins.c: CoreXY kinematics: two belt motors drive X and Y together (kinematics type BOTH, no pins). */
#include "rtapi.h"
#include "emc/kinematics/kins_frame.h"
#include "cartesian_math.h"

MODULE_DESCRIPTION("CoreXY kinematics: two belt motors drive X and Y together");

/* Joints -> world. */
static int corexy_fwd(const double *joints, EmcPose *pos)
{
    corexy_forward(joints, pos);
    return 0;
}

/* World -> joints. */
static int corexy_inv(const EmcPose *pos, double *joints)
{
    corexy_inverse(pos, joints);
    return 0;
}

const kins_frame_def_t kins_frame_def = {
    .name = "corexykins", .type = KINEMATICS_BOTH, .forward = corexy_fwd, .inverse = corexy_inv,
};
