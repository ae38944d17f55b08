/* rotatekins.c: Rotated kinematics: the XY joints are turned 45 degrees to the world (kinematics type BOTH, no pins). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "cartesian_math.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Rotated kinematics: the XY joints are turned 45 degrees to the world");

static int comp_id;

/* Joints -> world. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    (void)fflags;
    (void)iflags;
    rotate_forward(joint, world);
    return 0;
}

/* World -> joints. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    (void)iflags;
    (void)fflags;
    rotate_inverse(world, joint);
    return 0;
}

/* Both directions are available. */
KINEMATICS_TYPE kinematicsType(void)
{
    return KINEMATICS_BOTH;
}

/* Not switchable. */
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

KINS_EXPORT_OPS("rotatekins");

/* Register the pinless component. */
int rtapi_app_main(void)
{
    comp_id = hal_init("rotatekins");
    if (comp_id < 0)
        return comp_id;
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
