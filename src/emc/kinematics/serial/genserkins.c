/* genserkins.c: switchable kinematics of a general 6R chain (Denavit-Hartenberg pins or a URDF). */
#include <math.h>
#include <stdlib.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "genser_math.h"
#include "genser_urdf.h"

MODULE_DESCRIPTION("Switchable general serial (Denavit-Hartenberg or URDF) kinematics");

static char *urdf = NULL;
RTAPI_MP_STRING(urdf, "URDF file giving the chain instead of the A/ALPHA/D pins");
static char *urdf_scale = "1000";
RTAPI_MP_STRING(urdf_scale, "Machine units per URDF metre (default 1000: millimetres)");

/* The pins of the chain. */
typedef struct {
    hal_float_t *a[GENSER_JOINTS];
    hal_float_t *alpha[GENSER_JOINTS];
    hal_float_t *d[GENSER_JOINTS];
    hal_s32_t *unrotate[GENSER_JOINTS];
    hal_u32_t *max_iterations;
    hal_u32_t *last_iterations;
} genser_pins_t;

static genser_pins_t *genser_pins;
static genser_chain_t urdf_chain;
static int urdf_loaded;

/* Current chain from the pins. */
static void genser_params(genser_params_t *p)
{
    for (int i = 0; i < GENSER_JOINTS; i++) {
        p->a[i] = *genser_pins->a[i];
        p->alpha[i] = *genser_pins->alpha[i];
        p->d[i] = *genser_pins->d[i];
        p->unrotate[i] = *genser_pins->unrotate[i];
    }
    p->max_iterations = *genser_pins->max_iterations;
    p->chain = urdf_loaded ? &urdf_chain : NULL;
}

/* Joints -> tool pose. */
static int genser_fwd(const double *joints, EmcPose *pos)
{
    genser_params_t p;
    genser_params(&p);
    return genser_forward(&p, joints, pos);
}

/* Pose -> joints, iterating from the current joints; reports the count on last-iterations. */
static int genser_inv(const EmcPose *pos, double *joints)
{
    genser_params_t p;
    unsigned int used = 0;
    genser_params(&p);
    int r = genser_inverse(&p, pos, joints, &used);
    *genser_pins->last_iterations = used;
    return r;
}

/* Make the A-N, ALPHA-N, D-N and unrotate-N pins of joint n with the default chain. */
static int genser_joint_pins(int comp_id, int n, const genser_params_t *def)
{
    genser_pins_t *g = genser_pins;
    int r = hal_pin_float_newf(HAL_IN, &g->a[n], comp_id, "genserkins.A-%d", n);
    if (r == 0)
        r = hal_pin_float_newf(HAL_IN, &g->alpha[n], comp_id, "genserkins.ALPHA-%d", n);
    if (r == 0)
        r = hal_pin_float_newf(HAL_IN, &g->d[n], comp_id, "genserkins.D-%d", n);
    if (r == 0)
        r = hal_pin_s32_newf(HAL_IN, &g->unrotate[n], comp_id, "genserkins.unrotate-%d", n);
    if (r < 0)
        return r;
    *g->a[n] = def->a[n];
    *g->alpha[n] = def->alpha[n];
    *g->d[n] = def->d[n];
    *g->unrotate[n] = def->unrotate[n];
    return 0;
}

/* Read urdf= (when given) with urdf_scale=; 0 or -EINVAL after printing why. */
static int genser_load_urdf(void)
{
    char why[300];
    char *end = NULL;
    double scale = strtod(urdf_scale ? urdf_scale : "", &end);
    if (!urdf_scale || end == urdf_scale || *end || !isfinite(scale) || scale <= 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "genserkins: ERROR: urdf_scale '%s' is not a positive number\n",
                        urdf_scale ? urdf_scale : "");
        return -EINVAL;
    }
    int r = genser_urdf_load(urdf, scale, &urdf_chain, why, sizeof(why));
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "genserkins: ERROR: %s\n", why);
        return r;
    }
    urdf_loaded = 1;
    return 0;
}

/* Make every genserkins pin; read the URDF chain first when urdf= is given. */
static int genser_setup(int comp_id, const char *sparm)
{
    genser_params_t def;
    (void)sparm;
    if (urdf && *urdf && genser_load_urdf() < 0)
        return -EINVAL;
    genser_defaults(&def);
    genser_pins = hal_malloc(sizeof(*genser_pins));
    if (!genser_pins)
        return -ENOMEM;
    int r = hal_pin_u32_newf(HAL_IN, &genser_pins->max_iterations, comp_id,
                             "genserkins.max-iterations");
    if (r == 0)
        r = hal_pin_u32_newf(HAL_OUT, &genser_pins->last_iterations, comp_id,
                             "genserkins.last-iterations");
    for (int n = 0; r == 0 && n < GENSER_JOINTS; n++)
        r = genser_joint_pins(comp_id, n, &def);
    if (r < 0)
        return r;
    *genser_pins->max_iterations = def.max_iterations;
    *genser_pins->last_iterations = 0;
    return 0;
}

const switchkins_def_t switchkins_def = {
    .name = "genserkins", .default_coordinates = "XYZABC", .native_type = KINEMATICS_BOTH,
    .setup = genser_setup, .native_forward = genser_fwd, .native_inverse = genser_inv,
};
