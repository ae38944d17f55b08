/* pivot_math.c: tool-center-point math of the tilting-head machines (5axiskins, maxkins). */
#include <math.h>
#include "rotary_math.h"
#include "rot3.h"

#define DEG_TO_RAD (M_PI / 180.0)

/* Vector from the head pivot to the tool tip: length pivot+W, azimuth C, polar angle 180-B. */
static void pivot5_arm(double pivot_length, double b_deg, double c_deg, double w, double arm[3])
{
    double r = pivot_length + w;
    double polar = (180.0 - b_deg) * DEG_TO_RAD, azimuth = c_deg * DEG_TO_RAD;
    arm[0] = r * sin(polar) * cos(azimuth);
    arm[1] = r * sin(polar) * sin(azimuth);
    arm[2] = r * cos(polar);
}

/* world = joints + arm + pivot z (the pivot sits pivot_length above the joint point). */
int pivot5_forward(double pivot_length, const double joints[3], double b_deg, double c_deg,
                   double w, double world[3])
{
    double arm[3];
    pivot5_arm(pivot_length, b_deg, c_deg, w, arm);
    world[0] = joints[0] + arm[0];
    world[1] = joints[1] + arm[1];
    world[2] = joints[2] + pivot_length + arm[2];
    return rot3_all_finite(world, 3) ? 0 : -1;
}

/* joints = world - arm - pivot z. */
int pivot5_inverse(double pivot_length, const double world[3], double b_deg, double c_deg,
                   double w, double joints[3])
{
    double arm[3];
    pivot5_arm(pivot_length, b_deg, c_deg, w, arm);
    joints[0] = world[0] - arm[0];
    joints[1] = world[1] - arm[1];
    joints[2] = world[2] - pivot_length - arm[2];
    return rot3_all_finite(joints, 3) ? 0 : -1;
}

/* maxkins head terms: tilt of (pivot+W) by B and of the U slide by B. */
typedef struct {
    double xb, zb, xu, zu;   /* head X/Z shift of the pivot arm and of the U slide */
    double cos_c, sin_c;     /* table rotation */
} maxkins_terms_t;

/* Head and table terms of a B, C, U, W set. */
static maxkins_terms_t maxkins_terms(double pivot_length, int conventional, const double axes[9])
{
    double dir = conventional ? -1.0 : 1.0;
    double b = dir * axes[4] * DEG_TO_RAD, c = dir * axes[5] * DEG_TO_RAD;
    double arm = pivot_length + axes[8];
    maxkins_terms_t t = {arm * sin(b), arm * cos(b), axes[6] * cos(b), axes[6] * sin(b),
                         cos(c), sin(c)};
    return t;
}

/* Copy the six rotary/UVW values unchanged. */
static void maxkins_copy_extra(const double *from, double *to)
{
    for (int i = 3; i < 9; i++)
        to[i] = from[i];
}

/* Head tip in machine frame, turned into the table frame by C. */
int maxkins_forward(double pivot_length, int conventional, const double joints[9], double world[9])
{
    maxkins_terms_t t = maxkins_terms(pivot_length, conventional, joints);
    double mx = joints[0] + t.xb - t.xu;
    double my = joints[1] - joints[7];
    world[0] = t.cos_c * mx - t.sin_c * my;
    world[1] = t.sin_c * mx + t.cos_c * my;
    world[2] = joints[2] - t.zb + t.zu + pivot_length;
    maxkins_copy_extra(joints, world);
    return rot3_all_finite(world, 9) ? 0 : -1;
}

/* Table point turned back by C, then the head terms removed. */
int maxkins_inverse(double pivot_length, int conventional, const double world[9], double joints[9])
{
    maxkins_terms_t t = maxkins_terms(pivot_length, conventional, world);
    double mx = t.cos_c * world[0] + t.sin_c * world[1];
    double my = -t.sin_c * world[0] + t.cos_c * world[1];
    joints[0] = mx - t.xb + t.xu;
    joints[1] = my + world[7];
    joints[2] = world[2] + t.zb - t.zu - pivot_length;
    maxkins_copy_extra(world, joints);
    return rot3_all_finite(joints, 9) ? 0 : -1;
}
