/* xyzab_tdr_kins.c: xyzab_tdr_kins, dual rotary table A (about X) carrying B (about Y); 0 identity, 1 TCP. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_pins.h"
#include "emc/kinematics/kins_template.h"
#include "trsrn_math.h"

MODULE_DESCRIPTION("Switchable kinematics for a dual rotary table A (about X) carrying B (about Y)");

/* Pin order. */
enum { TDR_TOOL, TDR_XOFF, TDR_ZOFF, TDR_XR, TDR_YR, TDR_ZR, TDR_PINS };

static const kins_pin_def_t tdr_pin_defs[TDR_PINS] = {
    {"tool-offset-z", 0}, {"x-offset", 0}, {"z-offset", 0}, {"x-rot-point", 0}, {"y-rot-point", 0},
    {"z-rot-point", 0}};

static hal_float_t **pins;

/* Load-time pin of one instance: <prefix>.dummy (s32 OUT). */
static int instance(int comp_id, int i, const char *prefix)
{
    hal_s32_t **dummy = hal_malloc(sizeof(*dummy));
    (void)i;
    if (!dummy)
        return -ENOMEM;
    return hal_pin_s32_newf(HAL_OUT, dummy, comp_id, "%s.dummy", prefix);
}

/* The kinematics pins (float IN, 0), at the first type query. */
static int setup(int comp_id)
{
    return kins_float_pins(comp_id, "xyzab_tdr_kins", tdr_pin_defs, TDR_PINS, &pins);
}

/* Geometry from the pins (zero before they exist). */
static tdr_geom_t geometry(void)
{
    tdr_geom_t g = {0, 0, 0, 0, 0, 0};
    if (pins)
        g = (tdr_geom_t){*pins[TDR_TOOL], *pins[TDR_XOFF], *pins[TDR_ZOFF], *pins[TDR_XR], *pins[TDR_YR],
                         *pins[TDR_ZR]};
    return g;
}

/* Joints -> world (identity or TCP); A, B from the joints; C U V W are 0. */
static int forward(int t, const double *joints, EmcPose *pos)
{
    tdr_geom_t g = geometry();
    double xyz[3] = {joints[0], joints[1], joints[2]};
    if (t == 1)
        tdr_tcp_forward(&g, joints, xyz);
    pos->tran = (PmCartesian){xyz[0], xyz[1], xyz[2]};
    pos->a = joints[3];
    pos->b = joints[4];
    pos->c = pos->u = pos->v = pos->w = 0;
    return 0;
}

/* World -> joints 0..4 (identity or TCP); joints 3, 4 := A, B. */
static int inverse(int t, const EmcPose *pos, double *joints)
{
    tdr_geom_t g = geometry();
    double xyz[3] = {pos->tran.x, pos->tran.y, pos->tran.z};
    if (t == 1) {
        tdr_tcp_inverse(&g, xyz, pos->a, pos->b, joints);
    } else {
        joints[0] = xyz[0];
        joints[1] = xyz[1];
        joints[2] = xyz[2];
    }
    joints[3] = pos->a;
    joints[4] = pos->b;
    return 0;
}

const kins_template_def_t kins_template_def = {
    "xyzab_tdr_kins", "xyzab-tdr-kins", instance, setup, 2, forward, inverse,
};
