/* arm6_math.h: closed-form kinematics of a 6R arm with a spherical wrist (PUMA and 3-2-1 robots). */
#ifndef ARM6_MATH_H
#define ARM6_MATH_H

#include "emc/kinematics/emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Geometry in machine units (Craig's modified Denavit-Hartenberg parameters). */
typedef struct {
    double a1;  /* shoulder offset along the first link */
    double a2;  /* upper arm length (must not be 0) */
    double a3;  /* elbow offset */
    double d1;  /* base height of the shoulder */
    double d2;  /* lateral offset at the shoulder */
    double d3;  /* lateral offset at the elbow */
    double d4;  /* forearm length to the wrist centre */
    double d6;  /* wrist centre to tool point */
} arm6_params_t;

/* Inverse flags (the arm configuration), as forward reports them. */
#define ARM6_SHOULDER_RIGHT 0x01
#define ARM6_ELBOW_DOWN 0x02
#define ARM6_WRIST_FLIP 0x04
#define ARM6_SINGULAR 0x08

#define ARM6_JOINTS 6

/* Joints (degrees) -> tool pose (XYZ, roll/pitch/yaw ABC in degrees); sets the arm flags. */
int arm6_forward(const arm6_params_t *p, const double *joints, EmcPose *pos, unsigned long *iflags);
/* Pose -> joints for the configuration in flags; joints holds the current joints on entry
 * (used at a wrist singularity and to pick whole turns). 0, or -1 when out of reach. */
int arm6_inverse(const arm6_params_t *p, const EmcPose *pos, unsigned long flags, double *joints);
/* Pose -> joints of the configuration nearest to the current joints in joints; 0 or -1. */
int arm6_inverse_nearest(const arm6_params_t *p, const EmcPose *pos, double *joints);

#ifdef __cplusplus
}
#endif

#endif
