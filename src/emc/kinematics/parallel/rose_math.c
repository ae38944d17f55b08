/* rose_math.c: rose engine (polar XY): radius, Z and an endless rotary joint. */
#include <math.h>
#include "parallel_math.h"

#define DEG (M_PI / 180.0)

/* X/Y from radius J0 and angle J2, Z from J1; the turn counter follows J2. */
void rose_forward(rose_state_t *s, const double *joints, EmcPose *pos)
{
    double turns = floor((joints[2] + 180.0) / 360.0);
    pos->tran.x = joints[0] * cos(joints[2] * DEG);
    pos->tran.y = joints[0] * sin(joints[2] * DEG);
    pos->tran.z = joints[1];
    cart_pass_forward(joints, pos, 3);
    s->revolutions = turns;
    s->theta_degrees = joints[2] - 360.0 * turns;
    s->bigtheta_degrees = joints[2];
}

/* Radius and angle of X/Y; crossing +-180 degrees counts a turn so J2 never jumps. */
void rose_inverse(rose_state_t *s, const EmcPose *pos, double *joints)
{
    double r = hypot(pos->tran.x, pos->tran.y);
    if (r > 0.0) {
        double theta = atan2(pos->tran.y, pos->tran.x) / DEG;
        if (theta - s->theta_degrees > 180.0)
            s->revolutions -= 1.0;
        else if (theta - s->theta_degrees < -180.0)
            s->revolutions += 1.0;
        s->theta_degrees = theta;
        s->bigtheta_degrees = theta + 360.0 * s->revolutions;
    }
    joints[0] = r;
    joints[1] = pos->tran.z;
    joints[2] = s->bigtheta_degrees;
    cart_pass_inverse(pos, joints, 3);
}
