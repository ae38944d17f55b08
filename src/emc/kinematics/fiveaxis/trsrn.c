/* trsrn.c: pins and TCP glue shared by the 6-axis table-rotary/spindle-rotary-nutating modules. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_pins.h"
#include "rotary_math.h"
#include "tcpswitch.h"
#include "trsrn.h"

/* Pin order: table axis point x/y/z, head pivot x/y/z, nutation angle, tool offset. */
enum { TR_AXIS_X, TR_AXIS_Y, TR_AXIS_Z, TR_OFF_X, TR_OFF_Y, TR_OFF_Z, TR_NUT, TR_TOOL, TR_PINS };

static const kins_pin_def_t trsrn_pin_defs[TR_PINS] = {
    {"x-rot-axis", 0.0}, {"y-rot-axis", 0.0}, {"z-rot-axis", 0.0}, {"x-offset", 0.0},
    {"y-offset", 0.0}, {"z-offset", 0.0}, {"nut-angle", 0.0}, {"tool-offset", 0.0}
};

/* The geometry pins (all float IN), in trsrn_pin_defs order. */
static hal_float_t **pins;

/* Make the geometry pins under prefix; 0 or negative errno. */
int trsrn_setup(int comp_id, const char *prefix)
{
    return kins_float_pins(comp_id, prefix, trsrn_pin_defs, TR_PINS, &pins);
}

/* Geometry of the module's variant from the current pin values. */
static trsrn_geom_t trsrn_geom(void)
{
    trsrn_geom_t g;
    g.table_axis = trsrn_variant.table_axis;
    g.nutation_axis = trsrn_variant.nutation_axis;
    for (int i = 0; i < 3; i++) {
        g.rot_axis[i] = *pins[TR_AXIS_X + i];
        g.pivot[i] = *pins[TR_OFF_X + i];
    }
    g.nut_angle = *pins[TR_NUT];
    g.tool_offset = *pins[TR_TOOL];
    return g;
}

/* Copy the three rotary values (joint slots 3..5). */
static void copy_rotaries(const double *from, double *to)
{
    for (int i = TRSRN_TABLE; i <= TRSRN_NUTATION; i++)
        to[i] = from[i];
}

/* TCP forward of the module's variant (tcpswitch_def.tcp_forward). */
int trsrn_tcp_forward(const double *joints, double *world)
{
    trsrn_geom_t g = trsrn_geom();
    copy_rotaries(joints, world);
    return trsrn_forward(&g, joints, joints[TRSRN_TABLE], joints[TRSRN_SPINDLE],
                         joints[TRSRN_NUTATION], world);
}

/* TCP inverse of trsrn_tcp_forward. */
int trsrn_tcp_inverse(const double *world, double *joints)
{
    trsrn_geom_t g = trsrn_geom();
    copy_rotaries(world, joints);
    return trsrn_inverse(&g, world, world[TRSRN_TABLE], world[TRSRN_SPINDLE],
                         world[TRSRN_NUTATION], joints);
}
