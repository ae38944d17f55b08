/* rosekins.c: rose engine kinematics; pins report the rotary joint's turn count and angles. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_frame.h"
#include "parallel_math.h"

MODULE_DESCRIPTION("Rose engine kinematics (radius, Z, endless rotary)");

/* Status pins in HAL memory. */
typedef struct {
    hal_float_t *revolutions;
    hal_float_t *theta_degrees;
    hal_float_t *bigtheta_degrees;
} rose_pins_t;

static rose_pins_t *pins;
static rose_state_t state;

/* Copy the solver state to the pins. */
static void publish(void)
{
    *pins->revolutions = state.revolutions;
    *pins->theta_degrees = state.theta_degrees;
    *pins->bigtheta_degrees = state.bigtheta_degrees;
}

/* Joints -> world; also resynchronises the turn counter. */
static int rose_fwd(const double *joint, EmcPose *world)
{
    rose_forward(&state, joint, world);
    publish();
    return 0;
}

/* World -> joints, the rotary joint continuing across +-180 degrees. */
static int rose_inv(const EmcPose *world, double *joint)
{
    rose_inverse(&state, world, joint);
    publish();
    return 0;
}

/* Create rosekins.revolutions, .theta_degrees, .bigtheta_degrees (float OUT). */
static int make_pins(int comp_id)
{
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    state = (rose_state_t){0.0, 0.0, 0.0};
    if (hal_pin_float_newf(HAL_OUT, &pins->revolutions, comp_id, "rosekins.revolutions") < 0
        || hal_pin_float_newf(HAL_OUT, &pins->theta_degrees, comp_id,
                              "rosekins.theta_degrees") < 0
        || hal_pin_float_newf(HAL_OUT, &pins->bigtheta_degrees, comp_id,
                              "rosekins.bigtheta_degrees") < 0)
        return -EINVAL;
    publish();
    return 0;
}

const kins_frame_def_t kins_frame_def = {
    .name = "rosekins", .type = KINEMATICS_BOTH, .setup = make_pins,
    .setup_error = "cannot create pins", .forward = rose_fwd, .inverse = rose_inv,
};
