/* cartesian_math.h: pure math of corexykins, rotatekins, matrixkins and scorbot-kins (no HAL). */
#ifndef CARTESIAN_MATH_H
#define CARTESIAN_MATH_H

#include "emc/kinematics/emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

/* CoreXY: X=(J0+J1)/2, Y=(J0-J1)/2, J2..J8 = Z A B C U V W. */
void corexy_forward(const double *joints, EmcPose *pos);
/* CoreXY inverse: J0=X+Y, J1=X-Y, J2..J8 = Z A B C U V W. */
void corexy_inverse(const EmcPose *pos, double *joints);

/* Rotated XY: joints 0/1 are the X/Y axes turned by 45 degrees; J2..J8 = Z..W. */
void rotate_forward(const double *joints, EmcPose *pos);
/* Rotated XY inverse. */
void rotate_inverse(const EmcPose *pos, double *joints);

/* Row-major 3x3 correction matrix: joints J0..J2 = m * (X Y Z). */
typedef struct {
    double m[3][3];
} matrix3_t;

/* Joints from the pose: J0..J2 = m*(X,Y,Z), J3..J8 = A B C U V W. */
void matrix_inverse_kins(const matrix3_t *mat, const EmcPose *pos, double *joints);
/* Pose from joints with the inverted matrix; -1 when the matrix is singular. */
int matrix_forward_kins(const matrix3_t *mat, const double *joints, EmcPose *pos);

/* Scorbot ER-3 link dimensions in mm. */
typedef struct {
    double l0_horizontal;   /* base axis to shoulder axis, horizontal */
    double l0_vertical;     /* table to shoulder axis, vertical */
    double l1_length;       /* shoulder to elbow */
    double l2_length;       /* elbow to wrist */
} scorbot_dims_t;

/* The dimensions scorbot-kins uses. */
extern const scorbot_dims_t scorbot_er3_dims;
/* Wrist centre from base, shoulder, elbow angles (degrees); J3..J8 = A B C U V W. */
void scorbot_forward(const scorbot_dims_t *d, const double *joints, EmcPose *pos);
/* Angles for a wrist centre (elbow-up solution); -1 when it is out of reach. */
int scorbot_inverse(const scorbot_dims_t *d, const EmcPose *pos, double *joints);

/* Copy joints first..8 into the pose axes first..8 (axis order X Y Z A B C U V W). */
void cart_pass_forward(const double *joints, EmcPose *pos, int first);
/* Copy pose axes first..8 into joints first..8. */
void cart_pass_inverse(const EmcPose *pos, double *joints, int first);

#ifdef __cplusplus
}
#endif

#endif
