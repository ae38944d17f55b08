/* xyzacb_trsrn.c: xyzacb_trsrn (rotary table A, nutating secondary B, primary spindle rotary C); types 0 identity, 1 TCP, 2 TOOL. */
#include "rtapi.h"
#include "emc/kinematics/kins_template.h"
#include "trsrn.h"

MODULE_DESCRIPTION("Switchable kinematics: rotary table A, nutating secondary B, primary spindle rotary C");

static const trsrn_module_t module = {TRSRN_ACB, "xyzacb_trsrn_kins", "y-pivot", "y-rot-axis"};

/* The kinematics pins, at the first type query. */
static int setup(int comp_id)
{
    return trsrn_setup_pins(comp_id, &module);
}

/* Joints -> world of type t. */
static int forward(int t, const double *joints, EmcPose *pos)
{
    return trsrn_forward(&module, t, joints, pos);
}

/* World -> joints of type t. */
static int inverse(int t, const EmcPose *pos, double *joints)
{
    return trsrn_inverse(&module, t, pos, joints);
}

const kins_template_def_t kins_template_def = {
    "xyzacb_trsrn", "xyzacb-trsrn", trsrn_instance, setup, 3, forward, inverse,
};
