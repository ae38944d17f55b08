/* xyzab_tdr_kins.c: xyzab_tdr_kins, tilting table A carrying a rotary B; type 0 identity, 1 TCP. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_pins.h"
#include "rotary_math.h"
#include "tcpswitch.h"

MODULE_DESCRIPTION("Switchable kinematics for a table with tilt A (about X) carrying rotary B");

/* Pin order: rot point x/y/z, offset x/y/z, tool offset. */
enum { TDR_ROT_X, TDR_ROT_Y, TDR_ROT_Z, TDR_OFF_X, TDR_OFF_Y, TDR_OFF_Z, TDR_TOOL, TDR_PINS };

static const kins_pin_def_t tdr_pin_defs[TDR_PINS] = {
    {"x-rot-point", 0.0}, {"y-rot-point", 0.0}, {"z-rot-point", 0.0}, {"x-offset", 0.0},
    {"y-offset", 0.0}, {"z-offset", 0.0}, {"tool-offset", 0.0}
};

/* The geometry pins (all float IN), in tdr_pin_defs order. */
static hal_float_t **pins;

/* Make the geometry pins. */
static int setup(int comp_id, const char *prefix)
{
    return kins_float_pins(comp_id, prefix, tdr_pin_defs, TDR_PINS, &pins);
}

/* Geometry from the current pin values: A about X on the bed, B about Y on top. */
static table2_geom_t tdr_geom(void)
{
    table2_geom_t g = {ROT_X, ROT_Y, {0, 0, 0}, {0, 0, 0}, 0, 0};
    for (int i = 0; i < 3; i++) {
        g.rot_point[i] = *pins[TDR_ROT_X + i];
        g.offset[i] = *pins[TDR_OFF_X + i];
    }
    g.tool_offset = *pins[TDR_TOOL];
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
