/* fiveaxiskins.c: 5axiskins, switchable kinematics of a B/C tilting spindle head with a W quill. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "axis_map.h"
#include "rotary_math.h"

MODULE_DESCRIPTION("Switchable kinematics for a bridge mill with a B/C rotary spindle head");

#define FIVEAXIS_NAME "5axiskins"
#define FIVEAXIS_AXES "XYZBCW"

/* The module's pin, in HAL memory. */
typedef struct {
    hal_float_t *pivot_length;   /* 5axiskins.pivot-length: pivot to spindle nose at W=0 */
} fiveaxis_pins_t;

static fiveaxis_pins_t *pins;

/* Check coordinates= and make the pivot-length pin (default 250). */
static int setup(int comp_id, const char *sparm)
{
    (void)sparm;
    char missing = axis_map_missing(switchkins_coords(), FIVEAXIS_AXES);
    if (missing) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: coordinates need a joint for axis %c\n",
                        FIVEAXIS_NAME, missing);
        return -EINVAL;
    }
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    int r = hal_pin_float_newf(HAL_IN, &pins->pivot_length, comp_id, "%s.pivot-length",
                               FIVEAXIS_NAME);
    if (r == 0)
        *pins->pivot_length = 250.0;
    return r;
}

/* Joints -> tool tip: the arm of length pivot+W hangs from the pivot, tilted by B, turned by C. */
static int forward(const double *joints, EmcPose *pos)
{
    const kins_coords_t *coords = switchkins_coords();
    double axes[9], world[3];
    axis_map_joint_axes(coords, joints, axes);
    if (pivot5_forward(*pins->pivot_length, axes, axes[4], axes[5], axes[8], world) < 0)
        return -1;
    axis_map_forward_pose(coords, joints, world, pos);
    return 0;
}

/* Tool tip -> joints. */
static int inverse(const EmcPose *pos, double *joints)
{
    double world[3] = {pos->tran.x, pos->tran.y, pos->tran.z}, joint_xyz[3];
    if (pivot5_inverse(*pins->pivot_length, world, pos->b, pos->c, pos->w, joint_xyz) < 0)
        return -1;
    axis_map_inverse_joints(switchkins_coords(), pos, joint_xyz, joints);
    return 0;
}

const switchkins_def_t switchkins_def = {
    .name = FIVEAXIS_NAME, .default_coordinates = FIVEAXIS_AXES, .native_type = KINEMATICS_BOTH,
    .setup = setup, .native_forward = forward, .native_inverse = inverse,
};
