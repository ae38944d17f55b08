/* scorbot-kins.c: Scorbot ER-3 arm kinematics: base, shoulder and elbow angles to XYZ (kinematics type BOTH, no pins). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "cartesian_math.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Scorbot ER-3 arm kinematics: base, shoulder and elbow angles to XYZ");

static int comp_id;

/* Joints -> world. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    (void)fflags;
    (void)iflags;
    scorbot_forward(&scorbot_er3_dims, joint, world);
    return 0;
}

/* World -> joints. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    (void)iflags;
    (void)fflags;
    return scorbot_inverse(&scorbot_er3_dims, world, joint);
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

KINS_EXPORT_OPS("scorbot-kins");

/* Register the pinless component. */
int rtapi_app_main(void)
{
    comp_id = hal_init("scorbot-kins");
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
