/* scorbot-kins.c: Scorbot ER-3 arm kinematics: base, shoulder and elbow angles to XYZ (kinematics type BOTH, no pins). */
#include "rtapi.h"
#include "emc/kinematics/kins_frame.h"
#include "cartesian_math.h"

MODULE_DESCRIPTION("Scorbot ER-3 arm kinematics: base, shoulder and elbow angles to XYZ");

/* Joints -> world. */
static int scorbot_fwd(const double *joints, EmcPose *pos)
{
    scorbot_forward(&scorbot_er3_dims, joints, pos);
    return 0;
}

/* World -> joints. */
static int scorbot_inv(const EmcPose *pos, double *joints)
{
    return scorbot_inverse(&scorbot_er3_dims, pos, joints);
}

const kins_frame_def_t kins_frame_def = {
    .name = "scorbot-kins", .type = KINEMATICS_BOTH, .forward = scorbot_fwd, .inverse = scorbot_inv,
};
