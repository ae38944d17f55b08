/* xyzacb_trsrn.c: xyzacb_trsrn, rotary table A, spindle rotary C, nutating B; 0 identity, 1 TCP. */
#include "rtapi.h"
#include "rotary_math.h"
#include "tcpswitch.h"
#include "trsrn.h"

MODULE_DESCRIPTION("Switchable kinematics: rotary table A, spindle rotary C with nutating B head");

/* Table about X, nutation axis leaning from Y. */
const trsrn_variant_t trsrn_variant = {ROT_X, ROT_Y};

const tcpswitch_def_t tcpswitch_def = {
    "xyzacb_trsrn", "xyzacb-trsrn", "XYZACB", trsrn_setup, trsrn_tcp_forward, trsrn_tcp_inverse
};
