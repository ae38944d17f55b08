/* xyzab_tdr_kins.c: xyzab_tdr_kins, tilting table A carrying a rotary B; type 0 identity, 1 TCP. */
#include "rtapi.h"
#include "hal.h"
#include "rotary_math.h"
#include "tcpswitch.h"

MODULE_DESCRIPTION("Switchable kinematics for a table with tilt A (about X) carrying rotary B");

/* Pin order: rot point x/y/z, offset x/y/z, tool offset. */
enum { TDR_ROT_X, TDR_ROT_Y, TDR_ROT_Z, TDR_OFF_X, TDR_OFF_Y, TDR_OFF_Z, TDR_TOOL, TDR_PINS };

static const char *const tdr_pin_names[TDR_PINS] = {
    "x-rot-point", "y-rot-point", "z-rot-point", "x-offset", "y-offset", "z-offset", "tool-offset"
};

/* The geometry pins (all float IN). */
typedef struct {
    hal_float_t *value[TDR_PINS];
} tdr_pins_t;

static tdr_pins_t *pins;

/* Make the geometry pins. */
static int setup(int comp_id, const char *prefix)
{
    hal_float_t **slots[TDR_PINS];
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    for (int i = 0; i < TDR_PINS; i++)
        slots[i] = &pins->value[i];
    return tcpswitch_float_pins(comp_id, prefix, tdr_pin_names, slots, TDR_PINS);
}

/* Geometry from the current pin values: A about X on the bed, B about Y on top. */
static table2_geom_t tdr_geom(void)
{
    table2_geom_t g = {ROT_X, ROT_Y, {0, 0, 0}, {0, 0, 0}, 0, 0};
    for (int i = 0; i < 3; i++) {
        g.rot_point[i] = *pins->value[TDR_ROT_X + i];
        g.offset[i] = *pins->value[TDR_OFF_X + i];
    }
    g.tool_offset = *pins->value[TDR_TOOL];
    return g;
}

/* Joints XYZAB -> world XYZAB with tool center point. */
static int tcp_forward(const double *joints, double *world)
{
    table2_geom_t g = tdr_geom();
    world[3] = joints[3];
    world[4] = joints[4];
    return table2_forward(&g, joints, joints[3], joints[4], world);
}

/* World XYZAB -> joints XYZAB with tool center point. */
static int tcp_inverse(const double *world, double *joints)
{
    table2_geom_t g = tdr_geom();
    joints[3] = world[3];
    joints[4] = world[4];
    return table2_inverse(&g, world, world[3], world[4], joints);
}

const tcpswitch_def_t tcpswitch_def = {
    "xyzab_tdr_kins", "xyzab-tdr-kins", "XYZAB", setup, tcp_forward, tcp_inverse
};
