/* axis_map.h: joint<->axis plumbing shared by the switchable 5-axis modules (pure C). */
#ifndef FIVEAXIS_AXIS_MAP_H
#define FIVEAXIS_AXIS_MAP_H

#include "emc/kinematics/kins_coords.h"

/* First letter of `letters` that no joint drives, or 0 when every axis has a joint. */
char axis_map_missing(const kins_coords_t *coords, const char *letters);
/* Axis values seen at the joints: every driven axis takes its first joint, the rest are 0. */
void axis_map_joint_axes(const kins_coords_t *coords, const double *joints, double axes[9]);
/* Forward result: pos gets the driven axes from the joints, then XYZ from world_xyz. */
void axis_map_forward_pose(const kins_coords_t *coords, const double *joints,
                           const double world_xyz[3], EmcPose *pos);
/* Inverse result: every joint takes its axis of pos, with XYZ replaced by joint_xyz. */
void axis_map_inverse_joints(const kins_coords_t *coords, const EmcPose *pos,
                             const double joint_xyz[3], double *joints);

#endif
