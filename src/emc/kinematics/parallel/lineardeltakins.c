/* lineardeltakins.c: linear delta kinematics with rod length L and radius R pins. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "parallel_math.h"
#include "kins_glue.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Linear delta kinematics (three towers)");

/* Geometry pins in HAL memory. */
typedef struct {
    hal_float_t *l;
    hal_float_t *r;
} lineardelta_pins_t;

static lineardelta_pins_t *pins;
static int comp_id;

/* Current geometry from the pins. */
static lineardelta_geom_t geometry(void)
{
    lineardelta_geom_t g = {*pins->l, *pins->r};
    return g;
}

/* Carriage heights -> effector; non-zero when the rods cannot meet. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    lineardelta_geom_t g = geometry();
    (void)fflags;
    (void)iflags;
    return lineardelta_forward(&g, joint, world);
}

/* Effector -> carriage heights; non-zero when out of reach. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    lineardelta_geom_t g = geometry();
    (void)iflags;
    (void)fflags;
    return lineardelta_inverse(&g, world, joint);
}

KINS_GLUE_BOTH("lineardeltakins");

/* Create lineardeltakins.L and .R (float IN) with their defaults. */
static int make_pins(void)
{
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    if (hal_pin_float_newf(HAL_IN, &pins->l, comp_id, "lineardeltakins.L") < 0
        || hal_pin_float_newf(HAL_IN, &pins->r, comp_id, "lineardeltakins.R") < 0)
        return -EINVAL;
    *pins->l = 269.0;
    *pins->r = 130.25;
    return 0;
}

/* Register the component and its pins. */
int rtapi_app_main(void)
{
    comp_id = hal_init("lineardeltakins");
    if (comp_id < 0)
        return comp_id;
    int rc = make_pins();
    if (rc < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "lineardeltakins: ERROR: cannot create pins\n");
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
