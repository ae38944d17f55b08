/* rotatekins.c: Rotated kinematics: the XY joints are turned 45 degrees to the world (kinematics type BOTH, no pins). */
#include "rtapi.h"
#include "emc/kinematics/kins_frame.h"
#include "cartesian_math.h"

MODULE_DESCRIPTION("Rotated kinematics: the XY joints are turned 45 degrees to the world");

/* Joints -> world. */
static int rotate_fwd(const double *joints, EmcPose *pos)
{
    rotate_forward(joints, pos);
    return 0;
}

/* World -> joints. */
static int rotate_inv(const EmcPose *pos, double *joints)
{
    rotate_inverse(pos, joints);
    return 0;
}

const kins_frame_def_t kins_frame_def = {
    .name = "rotatekins", .type = KINEMATICS_BOTH, .forward = rotate_fwd, .inverse = rotate_inv,
};
