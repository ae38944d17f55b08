/* tripodkins.c: tripod kinematics; pins Bx, Cx, Cy place the second and third base joints. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "parallel_math.h"
#include "kins_glue.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Tripod kinematics (three struts of variable length)");

/* Geometry pins in HAL memory. */
typedef struct {
    hal_float_t *bx;
    hal_float_t *cx;
    hal_float_t *cy;
} tripod_pins_t;

static tripod_pins_t *pins;
static int comp_id;

/* Current geometry from the pins. */
static tripod_geom_t geometry(void)
{
    tripod_geom_t g = {*pins->bx, *pins->cx, *pins->cy};
    return g;
}

/* Strut lengths -> tool point; forward flag bit 0 picks the solution below the base. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    tripod_geom_t g = geometry();
    (void)iflags;
    return tripod_forward(&g, joint, world, fflags && (*fflags & 1));
}

/* Tool point -> strut lengths. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    tripod_geom_t g = geometry();
    (void)iflags;
    if (fflags)
        *fflags = world->tran.z < 0.0 ? 1 : 0;
    return tripod_inverse(&g, world, joint);
}

KINS_GLUE_BOTH("tripodkins");

/* Create tripodkins.Bx, .Cx, .Cy (float IN), all 1.0. */
static int make_pins(void)
{
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    if (hal_pin_float_newf(HAL_IN, &pins->bx, comp_id, "tripodkins.Bx") < 0
        || hal_pin_float_newf(HAL_IN, &pins->cx, comp_id, "tripodkins.Cx") < 0
        || hal_pin_float_newf(HAL_IN, &pins->cy, comp_id, "tripodkins.Cy") < 0)
        return -EINVAL;
    *pins->bx = *pins->cx = *pins->cy = 1.0;
    return 0;
}

/* Register the component and its pins. */
int rtapi_app_main(void)
{
    comp_id = hal_init("tripodkins");
    if (comp_id < 0)
        return comp_id;
    int rc = make_pins();
    if (rc < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "tripodkins: ERROR: cannot create pins\n");
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
