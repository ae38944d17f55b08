/* tripodkins.c: tripod kinematics; pins Bx, Cx, Cy place the second and third base joints. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_frame.h"
#include "emc/kinematics/kins_pins.h"
#include "parallel_math.h"

MODULE_DESCRIPTION("Tripod kinematics (three struts of variable length)");

/* tripodkins.Bx, .Cx, .Cy, all 1.0 at load. */
static const kins_pin_def_t tripod_pin_defs[3] = {{"Bx", 1.0}, {"Cx", 1.0}, {"Cy", 1.0}};

/* The geometry pins, in tripod_pin_defs order. */
static hal_float_t **pins;

/* Current geometry from the pins. */
static tripod_geom_t geometry(void)
{
    tripod_geom_t g = {*pins[0], *pins[1], *pins[2]};
    return g;
}

/* Strut lengths -> tool point; forward flag bit 0 picks the solution below the base. */
static int tripod_fwd(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    tripod_geom_t g = geometry();
    (void)iflags;
    return tripod_forward(&g, joint, world, fflags && (*fflags & 1));
}

/* Tool point -> strut lengths. */
static int tripod_inv(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    tripod_geom_t g = geometry();
    (void)iflags;
    if (fflags)
        *fflags = world->tran.z < 0.0 ? 1 : 0;
    return tripod_inverse(&g, world, joint);
}

/* Create tripodkins.Bx, .Cx, .Cy (float I/O, as LinuxCNC has them), all 1.0. */
static int make_pins(int comp_id)
{
    return kins_float_pins_dir(comp_id, "tripodkins", tripod_pin_defs, 3, HAL_IO, &pins);
}

const kins_frame_def_t kins_frame_def = {
    .name = "tripodkins", .type = KINEMATICS_BOTH, .setup = make_pins,
    .setup_error = "cannot create pins", .forward_flags = tripod_fwd, .inverse_flags = tripod_inv,
};
