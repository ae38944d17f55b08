/* xyzbca_trsrn.c: xyzbca_trsrn, rotary table B, spindle rotary C, nutating A; 0 identity, 1 TCP. */
#include "rtapi.h"
#include "rotary_math.h"
#include "tcpswitch.h"
#include "trsrn.h"

MODULE_DESCRIPTION("Switchable kinematics: rotary table B, spindle rotary C with nutating A head");

/* Table about Y, nutation axis leaning from X. */
const trsrn_variant_t trsrn_variant = {ROT_Y, ROT_X};

const tcpswitch_def_t tcpswitch_def = {
    "xyzbca_trsrn", "xyzbca-trsrn", "XYZBCA", trsrn_setup, trsrn_tcp_forward, trsrn_tcp_inverse
};
