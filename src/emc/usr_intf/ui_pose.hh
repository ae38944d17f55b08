// ui_pose.hh: pose helpers user interfaces share: component access by axis index and positions in the current coordinate system.
#ifndef UI_POSE_HH
#define UI_POSE_HH

#include "emc_nml.hh"

// Component i of a pose, in axis order X Y Z A B C U V W.
double ui_pose_at(const EmcPose &p, int i);
// A machine position in the current coordinate system, as DROs show it: minus the G5x
// offset and the tool offset, turned back by the XY rotation, minus the G92 offset.
void ui_relative_position(const EMC_TASK_STAT &t, const EmcPose &machine, double out[EMCMOT_MAX_AXIS]);

#endif
