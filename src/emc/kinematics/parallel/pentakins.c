/* pentakins.c: pentapod kinematics (LinuxCNC pentakins): geometry params, tool offset and Newton-solver pins. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_frame.h"
#include "parallel_math.h"

MODULE_DESCRIPTION("Pentapod kinematics (five struts, X Y Z A B)");

/* Geometry params and solver pins in HAL memory. */
typedef struct {
    hal_float_t base[PENTA_STRUTS][3];
    hal_float_t ring_r[PENTA_STRUTS];
    hal_float_t ring_z[PENTA_STRUTS];
    hal_float_t *tool_offset;
    hal_float_t *convergence;
    hal_u32_t *limit_iterations;
    hal_float_t *max_error;
    hal_u32_t *last_iterations;
    hal_u32_t *max_iterations;
} penta_pins_t;

static penta_pins_t *pins;

/* Current geometry and solver limits; the tool offset moves every base and effector height. */
static void geometry(penta_geom_t *g)
{
    double t = *pins->tool_offset;
    for (int k = 0; k < PENTA_STRUTS; k++) {
        for (int i = 0; i < 3; i++)
            g->base[k][i] = pins->base[k][i];
        g->base[k][2] += t;
        g->ring_r[k] = pins->ring_r[k];
        g->ring_z[k] = pins->ring_z[k] + t;
    }
    g->convergence = *pins->convergence;
    g->limit_iterations = *pins->limit_iterations;
    g->max_error = *pins->max_error;
}

/* Strut lengths -> pose by Newton iteration from the given pose; records iteration counts on success. */
static int penta_fwd(const double *joint, EmcPose *world)
{
    penta_geom_t g;
    unsigned used = 0;
    geometry(&g);
    int rc = penta_forward(&g, joint, world, &used);
    if (rc == 0) {
        *pins->last_iterations = used;
        if (used > *pins->max_iterations)
            *pins->max_iterations = used;
    }
    return rc;
}

/* Pose -> strut lengths. */
static int penta_inv(const EmcPose *world, double *joint)
{
    penta_geom_t g;
    geometry(&g);
    return penta_inverse(&g, world, joint);
}

/* Params pentakins.base.N.x/y/z and effector.N.r/z of one strut, with defaults. */
static int strut_params(int comp_id, int k)
{
    static const char axis[3] = {'x', 'y', 'z'};
    for (int i = 0; i < 3; i++) {
        if (hal_param_float_newf(HAL_RW, &pins->base[k][i], comp_id, "pentakins.base.%d.%c", k, axis[i]) < 0)
            return -EINVAL;
        pins->base[k][i] = penta_default_geom.base[k][i];
    }
    if (hal_param_float_newf(HAL_RW, &pins->ring_r[k], comp_id, "pentakins.effector.%d.r", k) < 0
        || hal_param_float_newf(HAL_RW, &pins->ring_z[k], comp_id, "pentakins.effector.%d.z", k) < 0)
        return -EINVAL;
    pins->ring_r[k] = penta_default_geom.ring_r[k];
    pins->ring_z[k] = penta_default_geom.ring_z[k];
    return 0;
}

/* Tool offset and solver pins with their defaults. */
static int solver_pins(int comp_id)
{
    if (hal_pin_float_newf(HAL_IN, &pins->tool_offset, comp_id, "pentakins.tool-offset") < 0
        || hal_pin_float_newf(HAL_IO, &pins->convergence, comp_id, "pentakins.convergence-criterion") < 0
        || hal_pin_u32_newf(HAL_IO, &pins->limit_iterations, comp_id, "pentakins.limit-iterations") < 0
        || hal_pin_float_newf(HAL_IO, &pins->max_error, comp_id, "pentakins.max-error") < 0
        || hal_pin_u32_newf(HAL_OUT, &pins->last_iterations, comp_id, "pentakins.last-iterations") < 0
        || hal_pin_u32_newf(HAL_OUT, &pins->max_iterations, comp_id, "pentakins.max-iterations") < 0)
        return -EINVAL;
    *pins->tool_offset = 0;
    *pins->convergence = penta_default_geom.convergence;
    *pins->limit_iterations = penta_default_geom.limit_iterations;
    *pins->max_error = penta_default_geom.max_error;
    *pins->last_iterations = 0;
    *pins->max_iterations = 0;
    return 0;
}

/* Create every pin and param. */
static int make_pins(int comp_id)
{
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    for (int k = 0; k < PENTA_STRUTS; k++)
        if (strut_params(comp_id, k) < 0)
            return -EINVAL;
    return solver_pins(comp_id);
}

const kins_frame_def_t kins_frame_def = {
    .name = "pentakins", .type = KINEMATICS_BOTH, .setup = make_pins,
    .setup_error = "cannot create pins", .forward = penta_fwd, .inverse = penta_inv,
};
