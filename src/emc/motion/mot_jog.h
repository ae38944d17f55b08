/* mot_jog.h: jog limits, refusals, jog wheels and the jog-stop inputs. */
#ifndef MOT_JOG_H
#define MOT_JOG_H

void mot_joint_jog_limits(int joint, double *lo, double *hi);
int mot_joint_jog_refused(int joint, double vel, int report);
int mot_axis_jog_refused(int axis, int report);
void mot_jog_wheels_joints(void);
void mot_jog_wheels_axes(void);
void mot_jog_stop_inputs(void);
int mot_jog_active(void);

#endif
