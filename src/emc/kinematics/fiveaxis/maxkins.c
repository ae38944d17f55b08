/* maxkins.c: maxkins, kinematics of a tabletop mill with a tilting B head and a rotary C table. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_frame.h"
#include "emc/kinematics/kins_coords.h"
#include "rotary_math.h"

MODULE_DESCRIPTION("Kinematics for a mill with a tilting B head and a rotary C table (XYZABCUVW)");

/* The module's pins. */
typedef struct {
    hal_float_t *pivot_length;            /* maxkins.pivot-length (IO, 0.666) */
    hal_bit_t *conventional_directions;   /* maxkins.conventional-directions (IN) */
} maxkins_pins_t;

static maxkins_pins_t *pins;

/* Copy a pose into the nine-value XYZABCUVW order. */
static void pose_to_axes(const EmcPose *pos, double axes[9])
{
    for (int a = 0; a < KINS_AXES; a++)
        axes[a] = kins_pose_get(pos, a);
}

/* Joints 0..8 (XYZABCUVW) -> world pose. */
static int maxkins_fwd(const double *joint, EmcPose *world)
{
    double axes[9];
    if (maxkins_forward(*pins->pivot_length, *pins->conventional_directions, joint, axes) < 0)
        return -1;
    for (int a = 0; a < KINS_AXES; a++)
        kins_pose_set(world, a, axes[a]);
    return 0;
}

/* World pose -> joints 0..8. */
static int maxkins_inv(const EmcPose *world, double *joint)
{
    double axes[9], joints[9];
    pose_to_axes(world, axes);
    if (maxkins_inverse(*pins->pivot_length, *pins->conventional_directions, axes, joints) < 0)
        return -1;
    for (int j = 0; j < KINS_AXES; j++)
        joint[j] = joints[j];
    return 0;
}

/* Make the pins. */
static int maxkins_make_pins(int comp_id)
{
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    int r = hal_pin_float_newf(HAL_IO, &pins->pivot_length, comp_id, "maxkins.pivot-length");
    if (r < 0)
        return r;
    *pins->pivot_length = 0.666;
    return hal_pin_bit_newf(HAL_IN, &pins->conventional_directions, comp_id,
                            "maxkins.conventional-directions");
}

/* Make the pins; report a failure with its code. */
static int maxkins_setup(int comp_id)
{
    int r = maxkins_make_pins(comp_id);
    if (r < 0)
        rtapi_print_msg(RTAPI_MSG_ERR, "maxkins: ERROR: pin export failed (%d)\n", r);
    return r;
}

const kins_frame_def_t kins_frame_def = {
    .name = "maxkins", .type = KINEMATICS_BOTH, .setup = maxkins_setup,
    .forward = maxkins_fwd, .inverse = maxkins_inv,
};
