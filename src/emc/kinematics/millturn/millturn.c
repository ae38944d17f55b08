/* millturn.c: switchable mill-turn kinematics: type 0 turning (X/Z swapped), type 1 milling (identity). */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "millturn_math.h"

MODULE_DESCRIPTION("Mill-turn kinematics: turning (type 0) and milling (type 1)");

#define MILLTURN_SLIDES 3   /* joints 0..2 are the X, Y and Z slides */

/* Joints beyond the slides follow their coordinates= letters (rotaries, U V W). */
static void extra_forward(const double *joints, EmcPose *pos)
{
    const kins_coords_t *map = switchkins_coords();
    for (int j = MILLTURN_SLIDES; j < map->joint_count; j++)
        kins_pose_set(pos, map->axis_of_joint[j], joints[j]);
}

/* Joints beyond the slides take their axis. */
static void extra_inverse(const EmcPose *pos, double *joints)
{
    const kins_coords_t *map = switchkins_coords();
    for (int j = MILLTURN_SLIDES; j < map->joint_count; j++)
        joints[j] = kins_pose_get(pos, map->axis_of_joint[j]);
}

/* Turning forward: swapped slides plus the extra joints. */
static int millturn_fwd(const double *joints, EmcPose *pos)
{
    millturn_turn_forward(joints, pos);
    extra_forward(joints, pos);
    return 0;
}

/* Turning inverse: swapped slides plus the extra joints. */
static int millturn_inv(const EmcPose *pos, double *joints)
{
    millturn_turn_inverse(pos, joints);
    extra_inverse(pos, joints);
    return 0;
}

/* The first three joints must be the X, Y and Z slides for the swap to mean anything. */
static int millturn_setup(int comp_id, const char *sparm)
{
    const kins_coords_t *map = switchkins_coords();
    (void)comp_id;
    (void)sparm;
    for (int j = 0; j < MILLTURN_SLIDES; j++) {
        if (j >= map->joint_count || map->axis_of_joint[j] != j) {
            rtapi_print_msg(RTAPI_MSG_ERR,
                            "millturn: ERROR: coordinates must start with XYZ (joints 0..2)\n");
            return -EINVAL;
        }
    }
    return 0;
}

/* What the switchable frame needs: name, identity map, type, setup and the two directions. */
const switchkins_def_t switchkins_def = {
    "millturn", "XYZC", KINEMATICS_BOTH, millturn_setup, millturn_fwd, millturn_inv, 0, NULL, NULL,
};
