/* scara_math.h: kinematics of a SCARA arm (two horizontal links, vertical quill, tool rotation). */
#ifndef SCARA_MATH_H
#define SCARA_MATH_H

#include "emc/kinematics/emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Geometry in machine units (the scarakins D1..D6 pins). */
typedef struct {
    double d1;  /* base to inner arm height */
    double d2;  /* inner arm length (joint 0 axis to joint 1 axis) */
    double d3;  /* inner arm to outer arm height */
    double d4;  /* outer arm length (joint 1 axis to quill axis) */
    double d5;  /* end effector to tool tip, downwards */
    double d6;  /* quill axis to tool tip, horizontal */
} scara_params_t;

#define SCARA_JOINTS 6
/* Inverse flag: the elbow angle (joint 1) is negative. */
#define SCARA_ELBOW_NEGATIVE 0x01

/* Joints (0, 1, 3 degrees; 2 linear; 4, 5 pass to A, B) -> pose; sets the elbow flag. */
int scara_forward(const scara_params_t *p, const double *joints, EmcPose *pos, unsigned long *iflags);
/* Pose -> joints with the elbow sign of flags; joints holds the current joints on entry
 * (whole turns are chosen near them). 0, or -1 when out of reach. */
int scara_inverse(const scara_params_t *p, const EmcPose *pos, unsigned long flags, double *joints);
/* Pose -> joints keeping the elbow sign of the current joint 1 (positive when it is 0). */
int scara_inverse_keep_elbow(const scara_params_t *p, const EmcPose *pos, double *joints);

#ifdef __cplusplus
}
#endif

#endif
