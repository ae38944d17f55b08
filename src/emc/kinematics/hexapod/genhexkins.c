/* genhexkins.c: switchable hexapod kinematics module: geometry pins and glue to genhex_math. */
#include <math.h>
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "genhex_math.h"

MODULE_DESCRIPTION("Generalized hexapod (Stewart platform) kinematics, switchable");

#define GUI_AXES 6

/* One x/y/z triple of pins. */
typedef struct {
    hal_float_t *x, *y, *z;
} vec_pins_t;

/* Every pin of the module. */
typedef struct {
    vec_pins_t base[GENHEX_STRUTS], platform[GENHEX_STRUTS];
    vec_pins_t base_n[GENHEX_STRUTS], platform_n[GENHEX_STRUTS];
    hal_float_t *spindle_offset, *tool_offset, *screw_lead;
    hal_float_t *conv_criterion, *max_error;
    hal_u32_t *limit_iterations, *last_iterations, *max_iterations;
    hal_float_t *gui[GUI_AXES];   /* skgui.x/y/z/a/b/c */
} genhex_pins_t;

static genhex_pins_t *pins;
static EmcPose last_pose;         /* guess for the next forward call */
static int have_last_pose;

/* Pin values -> geometry for the math. */
static void read_geometry(genhex_geom_t *g)
{
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        g->base[i] = (PmCartesian){*pins->base[i].x, *pins->base[i].y, *pins->base[i].z};
        g->platform[i] = (PmCartesian){*pins->platform[i].x, *pins->platform[i].y,
                                       *pins->platform[i].z};
        g->base_n[i] = (PmCartesian){*pins->base_n[i].x, *pins->base_n[i].y, *pins->base_n[i].z};
        g->platform_n[i] = (PmCartesian){*pins->platform_n[i].x, *pins->platform_n[i].y,
                                         *pins->platform_n[i].z};
    }
    g->screw_lead = *pins->screw_lead;
    g->tool_length = *pins->spindle_offset + *pins->tool_offset;
}

/* The last-resort start guess: platform level, at the height strut 0 allows. */
static void upright_guess(const genhex_geom_t *g, const double *joints, EmcPose *guess)
{
    double dx = g->platform[0].x - g->base[0].x, dy = g->platform[0].y - g->base[0].y;
    double h2 = joints[0] * joints[0] - dx * dx - dy * dy;
    *guess = (EmcPose){{0.0, 0.0, h2 > 1.0 ? sqrt(h2) : 1.0}, 0, 0, 0, 0, 0, 0};
}

/* Publish the iteration figures and the pose on skgui.*. */
static void report(const genhex_solve_t *s, const EmcPose *pos)
{
    *pins->last_iterations = s->iterations;
    if (s->iterations > *pins->max_iterations)
        *pins->max_iterations = s->iterations;
    const double v[GUI_AXES] = {pos->tran.x, pos->tran.y, pos->tran.z, pos->a, pos->b, pos->c};
    for (int i = 0; i < GUI_AXES; i++)
        *pins->gui[i] = v[i];
}

/* Strut lengths (joints 0..5) -> pose, starting from the caller's pose, then the last
 * solution, then an upright guess; -1 when none converges. */
static int genhex_fwd(const double *joints, EmcPose *pos)
{
    genhex_geom_t g;
    genhex_solve_t s = {*pins->conv_criterion, *pins->max_error, *pins->limit_iterations, 0, 0.0};
    EmcPose guess[3];
    int n = 0, r = -1, i;
    read_geometry(&g);
    guess[n++] = *pos;
    if (have_last_pose)
        guess[n++] = last_pose;
    upright_guess(&g, joints, &guess[n++]);
    for (i = 0; i < n; i++) {
        r = genhex_forward(&g, joints, &guess[i], &s);
        if (r == 0)
            break;
    }
    *pins->last_iterations = s.iterations;
    if (r < 0)
        return -1;
    report(&s, &guess[i]);
    last_pose = guess[i];
    have_last_pose = 1;
    pos->tran = guess[i].tran;
    pos->a = guess[i].a;
    pos->b = guess[i].b;
    pos->c = guess[i].c;
    return 0;
}

/* Pose -> strut lengths (joints 0..5). */
static int genhex_inv(const EmcPose *pos, double *joints)
{
    genhex_geom_t g;
    read_geometry(&g);
    return genhex_inverse(&g, pos, joints);
}

/* Make base.N / platform.N style pins named "genhexkins.<what>.N.x/y/z" with defaults. */
static int vec_pins(int comp_id, const char *what, vec_pins_t *v, const PmCartesian *init)
{
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        int r = hal_pin_float_newf(HAL_IN, &v[i].x, comp_id, "genhexkins.%s.%d.x", what, i);
        if (r == 0)
            r = hal_pin_float_newf(HAL_IN, &v[i].y, comp_id, "genhexkins.%s.%d.y", what, i);
        if (r == 0)
            r = hal_pin_float_newf(HAL_IN, &v[i].z, comp_id, "genhexkins.%s.%d.z", what, i);
        if (r < 0)
            return r;
        *v[i].x = init[i].x;
        *v[i].y = init[i].y;
        *v[i].z = init[i].z;
    }
    return 0;
}

/* Scalar pins of the solver and the tool, with their defaults. */
static int scalar_pins(int comp_id)
{
    int r = hal_pin_float_newf(HAL_IN, &pins->spindle_offset, comp_id, "genhexkins.spindle-offset");
    if (r == 0) r = hal_pin_float_newf(HAL_IN, &pins->tool_offset, comp_id, "genhexkins.tool-offset");
    if (r == 0) r = hal_pin_float_newf(HAL_IN, &pins->screw_lead, comp_id, "genhexkins.screw-lead");
    if (r == 0) r = hal_pin_float_newf(HAL_IN, &pins->conv_criterion, comp_id,
                                       "genhexkins.convergence-criterion");
    if (r == 0) r = hal_pin_u32_newf(HAL_IN, &pins->limit_iterations, comp_id,
                                     "genhexkins.limit-iterations");
    if (r == 0) r = hal_pin_float_newf(HAL_IN, &pins->max_error, comp_id, "genhexkins.max-error");
    if (r == 0) r = hal_pin_u32_newf(HAL_OUT, &pins->last_iterations, comp_id,
                                     "genhexkins.last-iterations");
    if (r == 0) r = hal_pin_u32_newf(HAL_OUT, &pins->max_iterations, comp_id,
                                     "genhexkins.max-iterations");
    if (r < 0)
        return r;
    *pins->conv_criterion = 1e-9;
    *pins->max_error = 500.0;
    *pins->limit_iterations = 120;
    return 0;
}

/* skgui.x/y/z/a/b/c: the pose of the last successful native forward solve. */
static int gui_pins(int comp_id)
{
    static const char axis[GUI_AXES] = {'x', 'y', 'z', 'a', 'b', 'c'};
    for (int i = 0; i < GUI_AXES; i++) {
        int r = hal_pin_float_newf(HAL_OUT, &pins->gui[i], comp_id, "skgui.%c", axis[i]);
        if (r < 0)
            return r;
    }
    return 0;
}

/* Create all pins with the default geometry. */
static int genhex_setup(int comp_id, const char *sparm)
{
    genhex_geom_t g;
    (void)sparm;
    genhex_default_geometry(&g);
    have_last_pose = 0;
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    int r = vec_pins(comp_id, "base", pins->base, g.base);
    if (r == 0) r = vec_pins(comp_id, "platform", pins->platform, g.platform);
    if (r == 0) r = vec_pins(comp_id, "base-n", pins->base_n, g.base_n);
    if (r == 0) r = vec_pins(comp_id, "platform-n", pins->platform_n, g.platform_n);
    if (r == 0) r = scalar_pins(comp_id);
    if (r == 0) r = gui_pins(comp_id);
    return r;
}

/* What the switchable frame needs: name, identity map, type, setup and the two directions. */
const switchkins_def_t switchkins_def = {
    "genhexkins", "XYZABC", KINEMATICS_BOTH, genhex_setup, genhex_fwd, genhex_inv, 0,
};
