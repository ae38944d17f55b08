/* pentakins.c: pentapod kinematics; base/ring geometry and Newton-solver pins. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "parallel_math.h"
#include "kins_glue.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Pentapod kinematics (five struts, X Y Z A B)");

/* Geometry and solver pins in HAL memory. */
typedef struct {
    hal_float_t *base[PENTA_STRUTS][3];
    hal_float_t *ring_r[PENTA_STRUTS];
    hal_float_t *ring_z[PENTA_STRUTS];
    hal_float_t *convergence;
    hal_u32_t *limit_iterations;
    hal_float_t *max_error;
    hal_u32_t *last_iterations;
    hal_u32_t *max_iterations;
} penta_pins_t;

static penta_pins_t *pins;
static int comp_id;

/* Current geometry and solver limits from the pins. */
static void geometry(penta_geom_t *g)
{
    for (int k = 0; k < PENTA_STRUTS; k++) {
        for (int i = 0; i < 3; i++)
            g->base[k][i] = *pins->base[k][i];
        g->ring_r[k] = *pins->ring_r[k];
        g->ring_z[k] = *pins->ring_z[k];
    }
    g->convergence = *pins->convergence;
    g->limit_iterations = *pins->limit_iterations;
    g->max_error = *pins->max_error;
}

/* Strut lengths -> pose by Newton iteration from the given pose; records iteration counts. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    penta_geom_t g;
    unsigned used = 0;
    (void)fflags;
    (void)iflags;
    geometry(&g);
    int rc = penta_forward(&g, joint, world, &used);
    *pins->last_iterations = used;
    if (used > *pins->max_iterations)
        *pins->max_iterations = used;
    return rc;
}

/* Pose -> strut lengths. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    penta_geom_t g;
    (void)iflags;
    (void)fflags;
    geometry(&g);
    return penta_inverse(&g, world, joint);
}

KINS_GLUE_BOTH("pentakins");

/* Create pentakins.base.N.x/y/z and effector.N.r/z for one strut, with defaults. */
static int strut_pins(int k)
{
    static const char axis[3] = {'x', 'y', 'z'};
    for (int i = 0; i < 3; i++) {
        if (hal_pin_float_newf(HAL_IN, &pins->base[k][i], comp_id, "pentakins.base.%d.%c",
                               k, axis[i]) < 0)
            return -EINVAL;
        *pins->base[k][i] = penta_default_geom.base[k][i];
    }
    if (hal_pin_float_newf(HAL_IN, &pins->ring_r[k], comp_id, "pentakins.effector.%d.r", k) < 0
        || hal_pin_float_newf(HAL_IN, &pins->ring_z[k], comp_id, "pentakins.effector.%d.z", k) < 0)
        return -EINVAL;
    *pins->ring_r[k] = penta_default_geom.ring_r[k];
    *pins->ring_z[k] = penta_default_geom.ring_z[k];
    return 0;
}

/* Create the solver pins with their defaults. */
static int solver_pins(void)
{
    if (hal_pin_float_newf(HAL_IN, &pins->convergence, comp_id,
                           "pentakins.convergence-criterion") < 0
        || hal_pin_u32_newf(HAL_IN, &pins->limit_iterations, comp_id,
                            "pentakins.limit-iterations") < 0
        || hal_pin_float_newf(HAL_IN, &pins->max_error, comp_id, "pentakins.max-error") < 0
        || hal_pin_u32_newf(HAL_OUT, &pins->last_iterations, comp_id,
                            "pentakins.last-iterations") < 0
        || hal_pin_u32_newf(HAL_OUT, &pins->max_iterations, comp_id,
                            "pentakins.max-iterations") < 0)
        return -EINVAL;
    *pins->convergence = penta_default_geom.convergence;
    *pins->limit_iterations = penta_default_geom.limit_iterations;
    *pins->max_error = penta_default_geom.max_error;
    *pins->last_iterations = 0;
    *pins->max_iterations = 0;
    return 0;
}

/* Create every pin. */
static int make_pins(void)
{
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    for (int k = 0; k < PENTA_STRUTS; k++)
        if (strut_pins(k) < 0)
            return -EINVAL;
    return solver_pins();
}

/* Register the component and its pins. */
int rtapi_app_main(void)
{
    comp_id = hal_init("pentakins");
    if (comp_id < 0)
        return comp_id;
    int rc = make_pins();
    if (rc < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "pentakins: ERROR: cannot create pins\n");
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
