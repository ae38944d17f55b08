/* xyzbca_trsrn.c: xyzbca_trsrn (rotary table B, nutating secondary A, primary spindle rotary C); types 0 identity, 1 TCP, 2 TOOL. */
#include "rtapi.h"
#include "emc/kinematics/kins_template.h"
#include "trsrn.h"

MODULE_DESCRIPTION("Switchable kinematics: rotary table B, nutating secondary A, primary spindle rotary C");

static const trsrn_module_t module = {TRSRN_BCA, "xyzbca_trsrn_kins", "x-pivot", "x-rot-axis"};

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
    "xyzbca_trsrn", "xyzbca-trsrn", trsrn_instance, setup, 3, forward, inverse,
};
