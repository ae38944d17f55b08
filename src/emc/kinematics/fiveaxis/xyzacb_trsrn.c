/* xyzacb_trsrn.c: xyzacb_trsrn, rotary table A, spindle rotary C, nutating B; 0 identity, 1 TCP. */
#include "rtapi.h"
#include "rotary_math.h"
#include "tcpswitch.h"
#include "trsrn.h"

MODULE_DESCRIPTION("Switchable kinematics: rotary table A, spindle rotary C with nutating B head");

/* TCP forward: table about X, nutation axis leaning from Y. */
static int tcp_forward(const double *joints, double *world)
{
    return trsrn_tcp_forward(ROT_X, ROT_Y, joints, world);
}

/* TCP inverse. */
static int tcp_inverse(const double *world, double *joints)
{
    return trsrn_tcp_inverse(ROT_X, ROT_Y, world, joints);
}

const tcpswitch_def_t tcpswitch_def = {
    "xyzacb_trsrn", "xyzacb-trsrn", "XYZACB", trsrn_setup, tcp_forward, tcp_inverse
};
