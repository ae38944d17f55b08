/* three21_math.h: LinuxCNC's three21kins (AR2-style 6-axis arm with a 3-2-1 wrist) as pure math. */
#ifndef THREE21_MATH_H
#define THREE21_MATH_H

#include "emc/kinematics/emcpos.h"

/* Link lengths and offsets (the three21kins.* pins). */
typedef struct {
    double a1, a2, a3, d1, d2, d3, d4, d6;
} three21_params_t;

/* Inverse flags (arm configuration) reported by forward, and the REACH forward flag of inverse. */
#define THREE21_SHOULDER_RIGHT 0x01
#define THREE21_ELBOW_DOWN 0x02
#define THREE21_WRIST_FLIP 0x04
#define THREE21_SINGULAR 0x08
#define THREE21_REACH 0x01

/* Joints 0..5 (degrees) -> X Y Z and roll/pitch/yaw A B C (degrees); *iflags gets the configuration. */
int three21_forward(const three21_params_t *p, const double *joints, EmcPose *pos, unsigned long *iflags);
/* Pose -> joints 0..5 for the configuration in iflags; joints[3] is kept at a wrist singularity (and
 * *fflags gets REACH). Always 0. */
int three21_inverse(const three21_params_t *p, const EmcPose *pos, unsigned long iflags, double *joints,
                    unsigned long *fflags);

#endif
