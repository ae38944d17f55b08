/* rotarydeltakins.c: rotary delta kinematics with platform, thigh, shin and foot (effector) radius pins. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_frame.h"
#include "emc/kinematics/kins_pins.h"
#include "parallel_math.h"

MODULE_DESCRIPTION("Rotary delta kinematics (three motors turning thighs)");

/* rotarydeltakins.* geometry pins with their defaults. */
static const kins_pin_def_t rotarydelta_pin_defs[4] = {
    {"platformradius", 10.0}, {"thighlength", 10.0}, {"shinlength", 14.0}, {"footradius", 6.0}
};

/* The geometry pins, in rotarydelta_pin_defs order. */
static hal_float_t **pins;

/* Current geometry from the pins. */
static rotarydelta_geom_t geometry(void)
{
    rotarydelta_geom_t g = {*pins[0], *pins[1], *pins[2], *pins[3]};
    return g;
}

/* Thigh angles -> effector; non-zero when the shins cannot meet. */
static int rotarydelta_fwd(const double *joint, EmcPose *world)
{
    rotarydelta_geom_t g = geometry();
    return rotarydelta_forward(&g, joint, world);
}

/* Effector -> thigh angles; non-zero when out of reach. */
static int rotarydelta_inv(const EmcPose *world, double *joint)
{
    rotarydelta_geom_t g = geometry();
    return rotarydelta_inverse(&g, world, joint);
}

/* Create the four geometry pins. */
static int make_pins(int comp_id)
{
    return kins_float_pins(comp_id, "rotarydeltakins", rotarydelta_pin_defs, 4, &pins);
}

const kins_frame_def_t kins_frame_def = {
    .name = "rotarydeltakins", .type = KINEMATICS_BOTH, .setup = make_pins,
    .setup_error = "cannot create pins", .forward = rotarydelta_fwd, .inverse = rotarydelta_inv,
};
