/* millturn_math.h: the turning-mode joint/axis map of the millturn kinematics, without HAL. */
#ifndef MILLTURN_MATH_H
#define MILLTURN_MATH_H

#include "emc/kinematics/emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Joints 0..2 (machine X, Y, Z slides) -> turning pose X, Y, Z; other axes untouched. */
void millturn_turn_forward(const double *joints, EmcPose *pos);
/* Turning pose X, Y, Z -> joints 0..2; other joints untouched. */
void millturn_turn_inverse(const EmcPose *pos, double *joints);

#ifdef __cplusplus
}
#endif

#endif
