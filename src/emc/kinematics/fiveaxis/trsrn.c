/* trsrn.c: pins and type dispatch shared by xyzacb_trsrn and xyzbca_trsrn. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_pins.h"
#include "trsrn.h"

/* Pin order; the pivot and rot-axis names depend on the machine. */
enum { TR_TOOL, TR_PIVOT, TR_ZPIVOT, TR_XOFF, TR_YOFF, TR_ROT, TR_ZROT, TR_PREROT, TR_NUT, TR_PRIMARY,
       TR_SECONDARY, TR_PINS };

static hal_float_t **pins;

/* Load-time pin of one instance: <prefix>.dummy (s32 OUT). */
int trsrn_instance(int comp_id, int i, const char *prefix)
{
    hal_s32_t **dummy = hal_malloc(sizeof(*dummy));
    (void)i;
    if (!dummy)
        return -ENOMEM;
    return hal_pin_s32_newf(HAL_OUT, dummy, comp_id, "%s.dummy", prefix);
}

/* The kinematics pins of module m (all float IN, 0). */
int trsrn_setup_pins(int comp_id, const trsrn_module_t *m)
{
    const kins_pin_def_t defs[TR_PINS] = {
        {"tool-offset-z", 0}, {m->pivot_pin, 0}, {"z-pivot", 0}, {"x-offset", 0}, {"y-offset", 0},
        {m->rot_axis_pin, 0}, {"z-rot-axis", 0}, {"pre-rot", 0}, {"nut-angle", 0}, {"primary-angle", 0},
        {"secondary-angle", 0}};
    return kins_float_pins(comp_id, m->pin_prefix, defs, TR_PINS, &pins);
}

/* Geometry from the pins (zero before they exist). */
static trsrn_geom_t trsrn_geom(void)
{
    trsrn_geom_t g = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    if (!pins)
        return g;
    g.dt = *pins[TR_TOOL];
    g.l_pivot = *pins[TR_PIVOT];
    g.lz = *pins[TR_ZPIVOT];
    g.dx = *pins[TR_XOFF];
    g.dy = *pins[TR_YOFF];
    g.rot_axis = *pins[TR_ROT];
    g.z_rot_axis = *pins[TR_ZROT];
    g.pre_rot = *pins[TR_PREROT];
    g.nut_angle = *pins[TR_NUT];
    g.primary = *pins[TR_PRIMARY];
    g.secondary = *pins[TR_SECONDARY];
    return g;
}

/* Joints -> world: identity, TCP or TOOL for X Y Z; A B C are the joints 3..5; U V W are 0. */
int trsrn_forward(const trsrn_module_t *m, int t, const double *joints, EmcPose *pos)
{
    trsrn_geom_t g = trsrn_geom();
    double xyz[3] = {joints[0], joints[1], joints[2]};
    if (t == 1)
        trsrn_tcp_forward(m->variant, &g, joints, xyz);
    else if (t == 2)
        trsrn_tool_forward(m->variant, &g, joints, xyz);
    pos->tran = (PmCartesian){xyz[0], xyz[1], xyz[2]};
    pos->a = joints[3];
    pos->b = joints[4];
    pos->c = joints[5];
    pos->u = pos->v = pos->w = 0;
    return 0;
}

/* World -> joints: identity, TCP (rotary angles from the joints passed in) or TOOL; joints 3..5 := A B C. */
int trsrn_inverse(const trsrn_module_t *m, int t, const EmcPose *pos, double *joints)
{
    trsrn_geom_t g = trsrn_geom();
    double xyz[3] = {pos->tran.x, pos->tran.y, pos->tran.z};
    if (t == 1) {
        trsrn_tcp_inverse(m->variant, &g, xyz, joints);
    } else if (t == 2) {
        trsrn_tool_inverse(m->variant, &g, xyz, joints);
    } else {
        joints[0] = xyz[0];
        joints[1] = xyz[1];
        joints[2] = xyz[2];
    }
    joints[3] = pos->a;
    joints[4] = pos->b;
    joints[5] = pos->c;
    return 0;
}
