/* rosekins.c: rose engine kinematics; pins report the rotary joint's turn count and angles. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "parallel_math.h"
#include "kins_glue.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Rose engine kinematics (radius, Z, endless rotary)");

/* Status pins in HAL memory. */
typedef struct {
    hal_float_t *revolutions;
    hal_float_t *theta_degrees;
    hal_float_t *bigtheta_degrees;
} rose_pins_t;

static rose_pins_t *pins;
static rose_state_t state;
static int comp_id;

/* Copy the solver state to the pins. */
static void publish(void)
{
    *pins->revolutions = state.revolutions;
    *pins->theta_degrees = state.theta_degrees;
    *pins->bigtheta_degrees = state.bigtheta_degrees;
}

/* Joints -> world; also resynchronises the turn counter. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    (void)fflags;
    (void)iflags;
    rose_forward(&state, joint, world);
    publish();
    return 0;
}

/* World -> joints, the rotary joint continuing across +-180 degrees. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    (void)iflags;
    (void)fflags;
    rose_inverse(&state, world, joint);
    publish();
    return 0;
}

KINS_GLUE_BOTH("rosekins");

/* Create rosekins.revolutions, .theta_degrees, .bigtheta_degrees (float OUT). */
static int make_pins(void)
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

/* Register the component and its pins. */
int rtapi_app_main(void)
{
    comp_id = hal_init("rosekins");
    if (comp_id < 0)
        return comp_id;
    int rc = make_pins();
    if (rc < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "rosekins: ERROR: cannot create pins\n");
        hal_exit(comp_id);
        return rc;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
