/* axis_map.c: joint<->axis plumbing shared by the switchable 5-axis modules (pure C). */
#include "axis_map.h"

/* First letter of `letters` that no joint drives, or 0 when every axis has a joint. */
char axis_map_missing(const kins_coords_t *coords, const char *letters)
{
    for (const char *p = letters; *p; p++)
        if (kins_coords_joint_of_axis(coords, kins_axis_index(*p)) < 0)
            return *p;
    return 0;
}

/* Axis values seen at the joints: every driven axis takes its first joint, the rest are 0. */
void axis_map_joint_axes(const kins_coords_t *coords, const double *joints, double axes[9])
{
    for (int axis = 0; axis < KINS_AXES; axis++) {
        int j = kins_coords_joint_of_axis(coords, axis);
        axes[axis] = j >= 0 ? joints[j] : 0.0;
    }
}

/* Forward result: pos gets the driven axes from the joints, then XYZ from world_xyz. */
void axis_map_forward_pose(const kins_coords_t *coords, const double *joints,
                           const double world_xyz[3], EmcPose *pos)
{
    kins_identity_forward(coords, joints, pos);
    pos->tran.x = world_xyz[0];
    pos->tran.y = world_xyz[1];
    pos->tran.z = world_xyz[2];
}

/* Inverse result: every joint takes its axis of pos, with XYZ replaced by joint_xyz. */
void axis_map_inverse_joints(const kins_coords_t *coords, const EmcPose *pos,
                             const double joint_xyz[3], double *joints)
{
    EmcPose at_joints = *pos;
    at_joints.tran.x = joint_xyz[0];
    at_joints.tran.y = joint_xyz[1];
    at_joints.tran.z = joint_xyz[2];
    kins_identity_inverse(coords, &at_joints, joints);
}
