/* trtkins.c: pins and joint mapping shared by the table-rotary-tilting (trt) kinematics modules. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "axis_map.h"
#include "rotary_math.h"
#include "trtkins.h"

/* The geometry pins (all IN). */
typedef struct {
    hal_float_t *offset[3];     /* x-offset y-offset z-offset */
    hal_float_t *rot_point[3];  /* x-rot-point y-rot-point z-rot-point */
    hal_float_t *tool_offset;
    hal_bit_t *conventional_directions;
} trtkins_pins_t;

static trtkins_pins_t *pins;

/* Make one float IN pin named <prefix>.<name>, starting at 0. */
static int float_pin(hal_float_t **pin, int comp_id, const char *prefix, const char *name)
{
    int r = hal_pin_float_newf(HAL_IN, pin, comp_id, "%s.%s", prefix, name);
    if (r == 0)
        **pin = 0.0;
    return r;
}

/* Create the geometry pins. */
static int trtkins_make_pins(const char *prefix, int comp_id)
{
    static const char *const rot_names[3] = {"x-rot-point", "y-rot-point", "z-rot-point"};
    static const char *const offset_names[3] = {"x-offset", "y-offset", "z-offset"};
    int r = 0;
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    for (int i = 0; i < 3 && r == 0; i++)
        r = float_pin(&pins->rot_point[i], comp_id, prefix, rot_names[i]);
    for (int i = 0; i < 3 && r == 0; i++)
        r = float_pin(&pins->offset[i], comp_id, prefix, offset_names[i]);
    if (r == 0)
        r = float_pin(&pins->tool_offset, comp_id, prefix, "tool-offset");
    if (r == 0)
        r = hal_pin_bit_newf(HAL_IN, &pins->conventional_directions, comp_id,
                             "%s.conventional-directions", prefix);
    return r;
}

/* Switchable-frame setup: check coordinates= and make the pins; 0 or negative errno. */
int trtkins_setup(int comp_id, const char *sparm)
{
    const trtkins_variant_t *v = &trtkins_variant;
    (void)sparm;
    char missing = axis_map_missing(switchkins_coords(), v->axes);
    if (missing) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: coordinates need a joint for axis %c\n",
                        v->name, missing);
        return -EINVAL;
    }
    return trtkins_make_pins(v->name, comp_id);
}

/* Geometry from the current pin values. */
static table2_geom_t trtkins_geom(const trtkins_variant_t *v)
{
    table2_geom_t g;
    g.primary_axis = v->primary_axis;
    g.secondary_axis = ROT_Z;
    for (int i = 0; i < 3; i++) {
        g.rot_point[i] = *pins->rot_point[i];
        g.offset[i] = *pins->offset[i];
    }
    g.tool_offset = *pins->tool_offset;
    g.conventional = *pins->conventional_directions ? 1 : 0;
    return g;
}

/* Native forward kinematics through the pins' geometry. */
int trtkins_forward(const double *joints, EmcPose *pos)
{
    const trtkins_variant_t *v = &trtkins_variant;
    const kins_coords_t *coords = switchkins_coords();
    table2_geom_t g = trtkins_geom(v);
    double axes[9], world[3];
    axis_map_joint_axes(coords, joints, axes);
    if (table2_forward(&g, axes, axes[v->primary_index], axes[5], world) < 0)
        return -1;
    axis_map_forward_pose(coords, joints, world, pos);
    return 0;
}

/* Native inverse kinematics through the pins' geometry. */
int trtkins_inverse(const EmcPose *pos, double *joints)
{
    const trtkins_variant_t *v = &trtkins_variant;
    table2_geom_t g = trtkins_geom(v);
    double world[3] = {pos->tran.x, pos->tran.y, pos->tran.z}, joint_xyz[3];
    double tilt = kins_pose_get(pos, v->primary_index);
    if (table2_inverse(&g, world, tilt, pos->c, joint_xyz) < 0)
        return -1;
    axis_map_inverse_joints(switchkins_coords(), pos, joint_xyz, joints);
    return 0;
}
