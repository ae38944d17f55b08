/* maxkins.c: maxkins, kinematics of a tabletop mill with a tilting B head and a rotary C table. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "emc/kinematics/kins_coords.h"
#include "rotary_math.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Kinematics for a mill with a tilting B head and a rotary C table (XYZABCUVW)");

/* The module's pins. */
typedef struct {
    hal_float_t *pivot_length;            /* maxkins.pivot-length (IO, 0.666) */
    hal_bit_t *conventional_directions;   /* maxkins.conventional-directions (IN) */
} maxkins_pins_t;

static maxkins_pins_t *pins;
static int comp_id;

/* Copy a pose into the nine-value XYZABCUVW order. */
static void pose_to_axes(const EmcPose *pos, double axes[9])
{
    for (int a = 0; a < KINS_AXES; a++)
        axes[a] = kins_pose_get(pos, a);
}

/* Joints 0..8 (XYZABCUVW) -> world pose. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    (void)fflags;
    (void)iflags;
    double axes[9];
    if (maxkins_forward(*pins->pivot_length, *pins->conventional_directions, joint, axes) < 0)
        return -1;
    for (int a = 0; a < KINS_AXES; a++)
        kins_pose_set(world, a, axes[a]);
    return 0;
}

/* World pose -> joints 0..8. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    (void)iflags;
    (void)fflags;
    double axes[9], joints[9];
    pose_to_axes(world, axes);
    if (maxkins_inverse(*pins->pivot_length, *pins->conventional_directions, axes, joints) < 0)
        return -1;
    for (int j = 0; j < KINS_AXES; j++)
        joint[j] = joints[j];
    return 0;
}

/* Both directions are available. */
KINEMATICS_TYPE kinematicsType(void)
{
    return KINEMATICS_BOTH;
}

/* maxkins cannot switch. */
int kinematicsSwitchable(void)
{
    return 0;
}

/* No-op: there is only one kinematics. */
int kinematicsSwitch(int switchkins_type)
{
    (void)switchkins_type;
    return 0;
}

KINS_EXPORT_OPS("maxkins");

/* Make the pins. */
static int maxkins_make_pins(void)
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

/* Register the component and its pins. */
int rtapi_app_main(void)
{
    comp_id = hal_init("maxkins");
    if (comp_id < 0)
        return comp_id;
    int r = maxkins_make_pins();
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "maxkins: ERROR: pin export failed (%d)\n", r);
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
