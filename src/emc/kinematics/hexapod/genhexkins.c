/* genhexkins.c: switchable hexapod kinematics module (LinuxCNC genhexkins): geometry pins, the solver
 * pins, the pose it solved and the skgui pose for GUIs. */
#include <math.h>
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "genhex_math.h"

MODULE_DESCRIPTION("Generalized hexapod (Stewart platform) kinematics, switchable");

#define POSE_AXES 6

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
    hal_bit_t *fwd_kins_fail;
    hal_float_t *correction[GENHEX_STRUTS];
    hal_float_t *pose[POSE_AXES];  /* genhexkins.x/y/z/a/b/c: the last solved pose */
    hal_float_t *gui[POSE_AXES];   /* skgui.x/y/z/a/b/c */
} genhex_pins_t;

static genhex_pins_t *pins;
static EmcPose saved_pose;        /* last forward result of the native kinematics */
static int fresh_switch;          /* the native type was just selected: start from saved_pose */

/* Pin values -> geometry for the math. */
static void read_geometry(genhex_geom_t *g)
{
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        g->base[i] = (PmCartesian){*pins->base[i].x, *pins->base[i].y, *pins->base[i].z};
        g->platform[i] = (PmCartesian){*pins->platform[i].x, *pins->platform[i].y, *pins->platform[i].z};
        g->base_n[i] = (PmCartesian){*pins->base_n[i].x, *pins->base_n[i].y, *pins->base_n[i].z};
        g->platform_n[i] = (PmCartesian){*pins->platform_n[i].x, *pins->platform_n[i].y,
                                         *pins->platform_n[i].z};
    }
    g->screw_lead = *pins->screw_lead;
    g->z_offset = *pins->spindle_offset + *pins->tool_offset;
}

/* Write a pose to six pins x y z a b c. */
static void put_pose(hal_float_t *const *out, const EmcPose *p)
{
    const double v[POSE_AXES] = {p->tran.x, p->tran.y, p->tran.z, p->a, p->b, p->c};
    for (int i = 0; i < POSE_AXES; i++)
        *out[i] = v[i];
}

/* Solve strut lengths for a pose starting from *pose; sets the status pins; 0 or a failure code. */
static int solve(const double *joints, EmcPose *pose)
{
    genhex_geom_t g;
    genhex_solve_t s = {*pins->conv_criterion, *pins->max_error, *pins->limit_iterations, 0};
    read_geometry(&g);
    for (int i = 0; i < GENHEX_STRUTS; i++)
        if (!(joints[i] > 0))
            return GENHEX_DEGENERATE;
    int r = genhex_forward(&g, joints, pose, &s);
    *pins->fwd_kins_fail = r != 0;
    if (r != 0)
        return r;
    *pins->last_iterations = s.iterations;
    if (s.iterations > *pins->max_iterations)
        *pins->max_iterations = s.iterations;
    put_pose(pins->pose, pose);
    return 0;
}

/* Strut lengths (joints 0..5) -> pose, from the pose given (or the saved one just after a switch). */
static int genhex_fwd(const double *joints, EmcPose *pos)
{
    EmcPose p = fresh_switch ? saved_pose : *pos;
    fresh_switch = 0;
    int r = solve(joints, &p);
    saved_pose = p;
    if (r == 0) {
        pos->tran = p.tran;
        pos->a = p.a;
        pos->b = p.b;
        pos->c = p.c;
    }
    return r;
}

/* After any successful forward: the native solution from the saved pose on skgui.*. */
static int genhex_gui(const double *joints)
{
    EmcPose p = saved_pose;
    int r = solve(joints, &p);
    saved_pose = p;
    if (r == 0)
        put_pose(pins->gui, &p);
    return r;
}

/* Selecting the native type makes its next forward start from the saved pose. */
static void genhex_switched(int new_type)
{
    if (new_type == 0)
        fresh_switch = 1;
}

/* Pose -> strut lengths (joints 0..5); with a screw lead, correction.N shows each length change. */
static int genhex_inv(const EmcPose *pos, double *joints)
{
    genhex_geom_t g;
    double corr[GENHEX_STRUTS];
    read_geometry(&g);
    int r = genhex_inverse(&g, pos, joints, corr);
    if (r == 0 && g.screw_lead != 0.0)
        for (int i = 0; i < GENHEX_STRUTS; i++)
            *pins->correction[i] = corr[i];
    return r;
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
    if (r == 0) r = hal_pin_float_newf(HAL_IN, &pins->conv_criterion, comp_id, "genhexkins.convergence-criterion");
    if (r == 0) r = hal_pin_u32_newf(HAL_IN, &pins->limit_iterations, comp_id, "genhexkins.limit-iterations");
    if (r == 0) r = hal_pin_float_newf(HAL_IN, &pins->max_error, comp_id, "genhexkins.max-error");
    if (r == 0) r = hal_pin_u32_newf(HAL_OUT, &pins->last_iterations, comp_id, "genhexkins.last-iterations");
    if (r == 0) r = hal_pin_u32_newf(HAL_OUT, &pins->max_iterations, comp_id, "genhexkins.max-iterations");
    if (r == 0) r = hal_pin_bit_newf(HAL_OUT, &pins->fwd_kins_fail, comp_id, "genhexkins.fwd-kins-fail");
    for (int i = 0; i < GENHEX_STRUTS && r == 0; i++)
        r = hal_pin_float_newf(HAL_OUT, &pins->correction[i], comp_id, "genhexkins.correction.%d", i);
    if (r < 0)
        return r;
    *pins->conv_criterion = 1e-9;
    *pins->max_error = 500.0;
    *pins->limit_iterations = 120;
    return 0;
}

/* genhexkins.x..c and skgui.x..c: IN pins the module writes (as LinuxCNC has them). */
static int pose_pins(int comp_id)
{
    static const char axis[POSE_AXES] = {'x', 'y', 'z', 'a', 'b', 'c'};
    for (int i = 0; i < POSE_AXES; i++) {
        int r = hal_pin_float_newf(HAL_IN, &pins->pose[i], comp_id, "genhexkins.%c", axis[i]);
        if (r == 0)
            r = hal_pin_float_newf(HAL_IN, &pins->gui[i], comp_id, "skgui.%c", axis[i]);
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
    saved_pose = (EmcPose){{0, 0, 0}, 0, 0, 0, 0, 0, 0};
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    int r = vec_pins(comp_id, "base", pins->base, g.base);
    if (r == 0) r = vec_pins(comp_id, "platform", pins->platform, g.platform);
    if (r == 0) r = vec_pins(comp_id, "base-n", pins->base_n, g.base_n);
    if (r == 0) r = vec_pins(comp_id, "platform-n", pins->platform_n, g.platform_n);
    if (r == 0) r = scalar_pins(comp_id);
    if (r == 0) r = pose_pins(comp_id);
    return r;
}

/* What the switchable frame needs: name, identity map, type, setup, the two directions, the GUI pose. */
const switchkins_def_t switchkins_def = {
    .name = "genhexkins", .default_coordinates = "XYZABC", .native_type = KINEMATICS_BOTH,
    .setup = genhex_setup, .native_forward = genhex_fwd, .native_inverse = genhex_inv,
    .after_forward = genhex_gui, .on_switch = genhex_switched,
};
