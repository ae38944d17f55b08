/* trsrn.c: pins and TCP glue shared by the 6-axis table-rotary/spindle-rotary-nutating modules. */
#include "rtapi.h"
#include "hal.h"
#include "rotary_math.h"
#include "tcpswitch.h"
#include "trsrn.h"

/* Pin order: table axis point x/y/z, head pivot x/y/z, nutation angle, tool offset. */
enum { TR_AXIS_X, TR_AXIS_Y, TR_AXIS_Z, TR_OFF_X, TR_OFF_Y, TR_OFF_Z, TR_NUT, TR_TOOL, TR_PINS };

static const char *const trsrn_pin_names[TR_PINS] = {
    "x-rot-axis", "y-rot-axis", "z-rot-axis", "x-offset", "y-offset", "z-offset",
    "nut-angle", "tool-offset"
};

/* The geometry pins (all float IN). */
typedef struct {
    hal_float_t *value[TR_PINS];
} trsrn_pins_t;

static trsrn_pins_t *pins;

/* Make the geometry pins under prefix; 0 or negative errno. */
int trsrn_setup(int comp_id, const char *prefix)
{
    hal_float_t **slots[TR_PINS];
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    for (int i = 0; i < TR_PINS; i++)
        slots[i] = &pins->value[i];
    return tcpswitch_float_pins(comp_id, prefix, trsrn_pin_names, slots, TR_PINS);
}

/* Geometry from the current pin values. */
static trsrn_geom_t trsrn_geom(int table_axis, int nutation_axis)
{
    trsrn_geom_t g;
    g.table_axis = table_axis;
    g.nutation_axis = nutation_axis;
    for (int i = 0; i < 3; i++) {
        g.rot_axis[i] = *pins->value[TR_AXIS_X + i];
        g.pivot[i] = *pins->value[TR_OFF_X + i];
    }
    g.nut_angle = *pins->value[TR_NUT];
    g.tool_offset = *pins->value[TR_TOOL];
    return g;
}

/* Copy the three rotary values (joint slots 3..5). */
static void copy_rotaries(const double *from, double *to)
{
    for (int i = TRSRN_TABLE; i <= TRSRN_NUTATION; i++)
        to[i] = from[i];
}

/* TCP forward for a table about table_axis and a nutation axis leaning from nutation_axis. */
int trsrn_tcp_forward(int table_axis, int nutation_axis, const double *joints, double *world)
{
    trsrn_geom_t g = trsrn_geom(table_axis, nutation_axis);
    copy_rotaries(joints, world);
    return trsrn_forward(&g, joints, joints[TRSRN_TABLE], joints[TRSRN_SPINDLE],
                         joints[TRSRN_NUTATION], world);
}

/* TCP inverse of trsrn_tcp_forward. */
int trsrn_tcp_inverse(int table_axis, int nutation_axis, const double *world, double *joints)
{
    trsrn_geom_t g = trsrn_geom(table_axis, nutation_axis);
    copy_rotaries(world, joints);
    return trsrn_inverse(&g, world, world[TRSRN_TABLE], world[TRSRN_SPINDLE],
                         world[TRSRN_NUTATION], joints);
}
