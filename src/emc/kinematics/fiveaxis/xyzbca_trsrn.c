/* xyzbca_trsrn.c: xyzbca_trsrn, rotary table B, spindle rotary C, nutating A; 0 identity, 1 TCP. */
#include "rtapi.h"
#include "rotary_math.h"
#include "tcpswitch.h"
#include "trsrn.h"

MODULE_DESCRIPTION("Switchable kinematics: rotary table B, spindle rotary C with nutating A head");

/* TCP forward: table about Y, nutation axis leaning from X. */
static int tcp_forward(const double *joints, double *world)
{
    return trsrn_tcp_forward(ROT_Y, ROT_X, joints, world);
}

/* TCP inverse. */
static int tcp_inverse(const double *world, double *joints)
{
    return trsrn_tcp_inverse(ROT_Y, ROT_X, world, joints);
}

const tcpswitch_def_t tcpswitch_def = {
    "xyzbca_trsrn", "xyzbca-trsrn", "XYZBCA", trsrn_setup, tcp_forward, tcp_inverse
};
