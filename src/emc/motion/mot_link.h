/* mot_link.h: finding the kinematics, planner and homing tables at load. */
#ifndef MOT_LINK_H
#define MOT_LINK_H

int mot_link_kins(void);
int mot_link_tp(void);
int mot_link_home(void);
void mot_unlink(void);

#endif
