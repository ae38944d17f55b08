/* rotarydeltakins.c: rotary delta kinematics with platform, thigh, shin and effector pins. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "parallel_math.h"
#include "kins_glue.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Rotary delta kinematics (three motors turning thighs)");

/* Geometry pins in HAL memory. */
typedef struct {
    hal_float_t *platform_radius;
    hal_float_t *thigh_length;
    hal_float_t *shin_length;
    hal_float_t *effector_radius;
} rotarydelta_pins_t;

static rotarydelta_pins_t *pins;
static int comp_id;

/* Current geometry from the pins. */
static rotarydelta_geom_t geometry(void)
{
    rotarydelta_geom_t g = {*pins->platform_radius, *pins->thigh_length, *pins->shin_length,
                            *pins->effector_radius};
    return g;
}

/* Thigh angles -> effector; non-zero when the shins cannot meet. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    rotarydelta_geom_t g = geometry();
    (void)fflags;
    (void)iflags;
    return rotarydelta_forward(&g, joint, world);
}

/* Effector -> thigh angles; non-zero when out of reach. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    rotarydelta_geom_t g = geometry();
    (void)iflags;
    (void)fflags;
    return rotarydelta_inverse(&g, world, joint);
}

KINS_GLUE_BOTH("rotarydeltakins");

/* Create one float IN pin rotarydeltakins.NAME with a default. */
static int geometry_pin(hal_float_t **pin, const char *name, double value)
{
    int rc = hal_pin_float_newf(HAL_IN, pin, comp_id, "rotarydeltakins.%s", name);
    if (rc < 0)
        return rc;
    **pin = value;
    return 0;
}

/* Create the four geometry pins. */
static int make_pins(void)
{
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    if (geometry_pin(&pins->platform_radius, "platformradius", 10.0) < 0
        || geometry_pin(&pins->thigh_length, "thighlength", 10.0) < 0
        || geometry_pin(&pins->shin_length, "shinlength", 14.0) < 0
        || geometry_pin(&pins->effector_radius, "effectorradius", 2.0) < 0)
        return -EINVAL;
    return 0;
}

/* Register the component and its pins. */
int rtapi_app_main(void)
{
    comp_id = hal_init("rotarydeltakins");
    if (comp_id < 0)
        return comp_id;
    int rc = make_pins();
    if (rc < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "rotarydeltakins: ERROR: cannot create pins\n");
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
