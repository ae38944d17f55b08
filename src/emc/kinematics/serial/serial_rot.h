/* serial_rot.h: rotation-matrix helpers shared by the serial-arm kinematics (pure math). */
#ifndef SERIAL_ROT_H
#define SERIAL_ROT_H

#include "emc/kinematics/emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SERIAL_DEG (180.0 / 3.14159265358979323846)

/* Row-major 3x3 rotation matrix. */
typedef double serial_mat3_t[3][3];

/* Rotation Rz(c) Ry(b) Rx(a) from roll a, pitch b, yaw c in degrees (world A, B, C). */
void serial_rot_from_rpy(double a_deg, double b_deg, double c_deg, serial_mat3_t r);
/* Roll, pitch, yaw in degrees of a rotation; at pitch +-90 the roll is reported as 0. */
void serial_rot_to_rpy(const serial_mat3_t r, double *a_deg, double *b_deg, double *c_deg);
/* out = x * y (out may not alias x or y). */
void serial_mat3_mul(const serial_mat3_t x, const serial_mat3_t y, serial_mat3_t out);
/* out = transpose(x) * y (out may not alias x or y). */
void serial_mat3_tmul(const serial_mat3_t x, const serial_mat3_t y, serial_mat3_t out);
/* Elementary rotation about axis 0 (x), 1 (y) or 2 (z) by angle_rad. */
void serial_mat3_axis(int axis, double angle_rad, serial_mat3_t out);
/* Set rounding-noise values (below 1e-12 in size) of a pose to exactly 0. */
void serial_pose_snap(EmcPose *pos);
/* Set rounding-noise values (below 1e-12 in size) of count joints to exactly 0. */
void serial_joints_snap(double *joints, int count);
/* angle_deg moved by whole turns to lie within half a turn of near_deg. */
double serial_angle_near(double angle_deg, double near_deg);

#ifdef __cplusplus
}
#endif

#endif
