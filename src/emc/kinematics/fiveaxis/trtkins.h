/* trtkins.h: shared HAL glue of xyzac-trt-kins and xyzbc-trt-kins (pins, joint map, TCP). */
#ifndef FIVEAXIS_TRTKINS_H
#define FIVEAXIS_TRTKINS_H

#include "emc/kinematics/emcpos.h"

/* What differs between the two trt machines. */
typedef struct {
    const char *name;      /* HAL prefix, e.g. "xyzac-trt-kins" */
    const char *axes;      /* axes the native kinematics needs, e.g. "XYZAC" */
    int primary_axis;      /* ROT_X for A, ROT_Y for B */
    int primary_index;     /* axis index of the tilt in EmcPose order (3 A, 4 B) */
} trtkins_variant_t;

/* The variant of the module being built; each trt module defines it. */
extern const trtkins_variant_t trtkins_variant;

/* Switchable-frame setup: check coordinates= and make the pins; 0 or negative errno. */
int trtkins_setup(int comp_id, const char *sparm);
/* Native forward kinematics through the pins' geometry. */
int trtkins_forward(const double *joints, EmcPose *pos);
/* Native inverse kinematics through the pins' geometry. */
int trtkins_inverse(const EmcPose *pos, double *joints);

#endif
