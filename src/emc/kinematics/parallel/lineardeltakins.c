/* lineardeltakins.c: linear delta kinematics with rod length L and radius R pins. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_frame.h"
#include "emc/kinematics/kins_pins.h"
#include "parallel_math.h"

MODULE_DESCRIPTION("Linear delta kinematics (three towers)");

/* lineardeltakins.L (rod length) and .R (radius) with their defaults. */
static const kins_pin_def_t lineardelta_pin_defs[2] = {{"L", 269.0}, {"R", 130.25}};

/* The geometry pins, in lineardelta_pin_defs order. */
static hal_float_t **pins;

/* Current geometry from the pins. */
static lineardelta_geom_t geometry(void)
{
    lineardelta_geom_t g = {*pins[0], *pins[1]};
    return g;
}

/* Carriage heights -> effector; non-zero when the rods cannot meet. */
static int lineardelta_fwd(const double *joint, EmcPose *world)
{
    lineardelta_geom_t g = geometry();
    return lineardelta_forward(&g, joint, world);
}

/* Effector -> carriage heights; non-zero when out of reach. */
static int lineardelta_inv(const EmcPose *world, double *joint)
{
    lineardelta_geom_t g = geometry();
    return lineardelta_inverse(&g, world, joint);
}

/* Create lineardeltakins.L and .R (float IN) with their defaults. */
static int make_pins(int comp_id)
{
    return kins_float_pins(comp_id, "lineardeltakins", lineardelta_pin_defs, 2, &pins);
}

const kins_frame_def_t kins_frame_def = {
    .name = "lineardeltakins", .type = KINEMATICS_BOTH, .setup = make_pins,
    .setup_error = "cannot create pins", .forward = lineardelta_fwd, .inverse = lineardelta_inv,
};
