/* serial_unit.h: shared checks and printing of the serial-arm kinematics unit tests. */
#ifndef SERIAL_UNIT_H
#define SERIAL_UNIT_H

#include "emc/kinematics/emcpos.h"

/* Count a check; print the label when it fails. */
void su_check(int ok, const char *label);
/* Print a pose with six decimals (no negative zero). */
void su_print_pose(const char *label, int rc, const EmcPose *p);
/* Print n joints with six decimals (no negative zero). */
void su_print_joints(const char *label, int rc, const double *j, int n);
/* Largest difference of position (units) and ABC (degrees, modulo 360) between two poses. */
double su_pose_diff(const EmcPose *x, const EmcPose *y);
/* Largest difference of n joint angles modulo 360. */
double su_angle_diff(const double *x, const double *y, int n);
/* Deterministic pseudo-random number in [lo, hi). */
double su_random(double lo, double hi);

/* Test groups. */
void su_arm6_tests(void);
void su_genser_tests(void);
void su_three21_tests(void);

#endif
