/* mot_coord.h: coordinated-mode cycle and helpers shared with the teleop/free paths. */
#ifndef MOT_COORD_H
#define MOT_COORD_H

#include "mot_priv.h"

void mot_coord_cmds(void);
int mot_coord_settled(void);
const mot_shadow_seg_t *mot_executing_segment(void);
int mot_pose_to_joints(const EmcPose *pos, double *joints);
void mot_joint_set_cmd(mot_joint_t *joint, double pos);

#endif
