/* genser_math.h: kinematics of a general 6R serial chain given by Denavit-Hartenberg parameters. */
#ifndef GENSER_MATH_H
#define GENSER_MATH_H

#include "emc/kinematics/emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GENSER_JOINTS 6
#define GENSER_DEFAULT_MAX_ITERATIONS 100
/* Hard cap on max_iterations, so one inverse call stays short in the servo thread. */
#define GENSER_ITERATION_LIMIT 1000

/* A chain read from a robot description: before joint i a fixed transform (rotation rot[i],
 * then translation tran[i], both relative to the previous joint's frame), then a rotation about
 * axis[i] (unit vector); after the last joint the fixed tool transform. */
typedef struct {
    double rot[GENSER_JOINTS][3][3];
    double tran[GENSER_JOINTS][3];
    double axis[GENSER_JOINTS][3];
    double tool_rot[3][3];
    double tool_tran[3];
} genser_chain_t;

/* Link i: Rx(alpha[i]) Tx(a[i]) Rz(joint i) Tz(d[i]) (Craig's convention; lengths in machine
 * units, alpha in radians), unless chain is set: then chain describes the links instead.
 * unrotate[i] subtracts unrotate[i] times the previous joint angle. */
typedef struct {
    double a[GENSER_JOINTS];
    double alpha[GENSER_JOINTS];
    double d[GENSER_JOINTS];
    int unrotate[GENSER_JOINTS];
    unsigned int max_iterations;
    const genser_chain_t *chain;
} genser_params_t;

/* Fill p with the PUMA 560-like defaults of the genserkins pins. */
void genser_defaults(genser_params_t *p);
/* Joints (degrees) -> tool pose (XYZ, roll/pitch/yaw ABC in degrees). Always 0. */
int genser_forward(const genser_params_t *p, const double *joints, EmcPose *pos);
/* Pose -> joints by damped Newton iteration seeded with the joints passed in; iterations gets
 * the count used. 0, or -1 (joints untouched) when it does not converge within max_iterations
 * (at most GENSER_ITERATION_LIMIT). */
int genser_inverse(const genser_params_t *p, const EmcPose *pos, double *joints,
                   unsigned int *iterations);

#ifdef __cplusplus
}
#endif

#endif
