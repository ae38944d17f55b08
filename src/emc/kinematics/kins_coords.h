/* kins_coords.h: the coordinates= joint-to-axis map of identity-style kinematics, and pose access. */
#ifndef KINS_COORDS_H
#define KINS_COORDS_H

#include <stddef.h>
#include "kins_ops.h"

#ifdef __cplusplus
extern "C" {
#endif

#define KINS_AXES 9                     /* X Y Z A B C U V W */
#define KINS_DEFAULT_COORDINATES "XYZABCUVW"

/* Which axis each joint drives, in joint order. */
typedef struct {
    int joint_count;
    int axis_of_joint[KINS_MAX_JOINTS];
} kins_coords_t;

/* Axis index 0..8 of a letter (any case), or -1. */
int kins_axis_index(char letter);
/* Axis letter (upper case) of an index 0..8. */
char kins_axis_letter(int axis);
/* Parse coordinates= (blanks ignored; NULL or empty = default); 0 or -EINVAL with why filled. */
int kins_coords_parse(const char *text, kins_coords_t *coords, char *why, size_t why_size);
/* First joint driving axis, or -1 when no joint does. */
int kins_coords_joint_of_axis(const kins_coords_t *coords, int axis);
/* Value of axis 0..8 of a pose. */
double kins_pose_get(const EmcPose *pos, int axis);
/* Set axis 0..8 of a pose. */
void kins_pose_set(EmcPose *pos, int axis, double value);
/* Identity forward: each mapped axis takes its first joint; unmapped axes are left alone. */
void kins_identity_forward(const kins_coords_t *coords, const double *joints, EmcPose *pos);
/* Identity inverse: every joint takes its axis (duplicate letters give equal joints). */
void kins_identity_inverse(const kins_coords_t *coords, const EmcPose *pos, double *joints);

#ifdef __cplusplus
}
#endif

#endif
