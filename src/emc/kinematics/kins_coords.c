/* kins_coords.c: coordinates= parsing and identity joint<->axis mapping (pure math, no HAL). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "kins_coords.h"

static const char axis_letters[KINS_AXES + 1] = "XYZABCUVW";

/* Axis index 0..8 of a letter (any case), or -1. */
int kins_axis_index(char letter)
{
    if (letter >= 'a' && letter <= 'z')
        letter = (char)(letter - 'a' + 'A');
    const char *p = letter ? strchr(axis_letters, letter) : NULL;
    return p ? (int)(p - axis_letters) : -1;
}

/* Axis letter (upper case) of an index 0..8. */
char kins_axis_letter(int axis)
{
    return axis >= 0 && axis < KINS_AXES ? axis_letters[axis] : '?';
}

/* Parse coordinates= (blanks ignored; NULL or empty = default); 0 or -EINVAL with why filled. */
int kins_coords_parse(const char *text, kins_coords_t *coords, char *why, size_t why_size)
{
    const char *src = text && *text ? text : KINS_DEFAULT_COORDINATES;
    coords->joint_count = 0;
    for (const char *p = src; *p; p++) {
        if (*p == ' ' || *p == '\t')
            continue;
        int axis = kins_axis_index(*p);
        if (axis < 0) {
            snprintf(why, why_size, "Invalid character '%c' in coordinates '%s'", *p, src);
            return -EINVAL;
        }
        if (coords->joint_count >= KINS_MAX_JOINTS) {
            snprintf(why, why_size, "coordinates '%s' name more than %d joints",
                     src, KINS_MAX_JOINTS);
            return -EINVAL;
        }
        coords->axis_of_joint[coords->joint_count++] = axis;
    }
    if (coords->joint_count == 0) {
        snprintf(why, why_size, "coordinates '%s' name no axis", src);
        return -EINVAL;
    }
    return 0;
}

/* First joint driving axis, or -1 when no joint does. */
int kins_coords_joint_of_axis(const kins_coords_t *coords, int axis)
{
    for (int j = 0; j < coords->joint_count; j++)
        if (coords->axis_of_joint[j] == axis)
            return j;
    return -1;
}

/* Value of axis 0..8 of a pose. */
double kins_pose_get(const EmcPose *pos, int axis)
{
    switch (axis) {
    case 0: return pos->tran.x;
    case 1: return pos->tran.y;
    case 2: return pos->tran.z;
    case 3: return pos->a;
    case 4: return pos->b;
    case 5: return pos->c;
    case 6: return pos->u;
    case 7: return pos->v;
    case 8: return pos->w;
    default: return 0.0;
    }
}

/* Set axis 0..8 of a pose. */
void kins_pose_set(EmcPose *pos, int axis, double value)
{
    switch (axis) {
    case 0: pos->tran.x = value; break;
    case 1: pos->tran.y = value; break;
    case 2: pos->tran.z = value; break;
    case 3: pos->a = value; break;
    case 4: pos->b = value; break;
    case 5: pos->c = value; break;
    case 6: pos->u = value; break;
    case 7: pos->v = value; break;
    case 8: pos->w = value; break;
    default: break;
    }
}

/* Identity forward: each mapped axis takes its first joint; unmapped axes are left alone. */
void kins_identity_forward(const kins_coords_t *coords, const double *joints, EmcPose *pos)
{
    for (int axis = 0; axis < KINS_AXES; axis++) {
        int j = kins_coords_joint_of_axis(coords, axis);
        if (j >= 0)
            kins_pose_set(pos, axis, joints[j]);
    }
}

/* Identity inverse: every joint takes its axis (duplicate letters give equal joints). */
void kins_identity_inverse(const kins_coords_t *coords, const EmcPose *pos, double *joints)
{
    for (int j = 0; j < coords->joint_count; j++)
        joints[j] = kins_pose_get(pos, coords->axis_of_joint[j]);
}
