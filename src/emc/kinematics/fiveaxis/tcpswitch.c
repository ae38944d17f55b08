/* tcpswitch.c: entry points and exports of the TCP kinematics (0 identity, 1 tool center point). */
#include <string.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "emc/kinematics/kins_coords.h"
#include "tcpswitch.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");

#define TCPSWITCH_MAX_JOINTS 9

static int active_type;   /* 0 identity, 1 TCP */
static int comp_id;

/* Number of joints of the module. */
static int joint_count(void)
{
    return (int)strlen(tcpswitch_def.axes);
}

/* Joints -> world: identity (type 0) or TCP (type 1). */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    (void)fflags;
    (void)iflags;
    double axes[TCPSWITCH_MAX_JOINTS];
    int n = joint_count();
    if (active_type == 1) {
        if (tcpswitch_def.tcp_forward(joint, axes) < 0)
            return -1;
    } else {
        memcpy(axes, joint, n * sizeof(double));
    }
    for (int j = 0; j < n; j++)
        kins_pose_set(world, kins_axis_index(tcpswitch_def.axes[j]), axes[j]);
    return 0;
}

/* World -> joints: identity (type 0) or TCP (type 1). */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    (void)iflags;
    (void)fflags;
    double axes[TCPSWITCH_MAX_JOINTS], joints[TCPSWITCH_MAX_JOINTS];
    int n = joint_count();
    for (int j = 0; j < n; j++)
        axes[j] = kins_pose_get(world, kins_axis_index(tcpswitch_def.axes[j]));
    if (active_type == 1) {
        if (tcpswitch_def.tcp_inverse(axes, joints) < 0)
            return -1;
    } else {
        memcpy(joints, axes, n * sizeof(double));
    }
    memcpy(joint, joints, n * sizeof(double));
    return 0;
}

/* Both kinematics do both directions. */
KINEMATICS_TYPE kinematicsType(void)
{
    return KINEMATICS_BOTH;
}

/* These modules can switch. */
int kinematicsSwitchable(void)
{
    return 1;
}

/* Select 0 (identity) or 1 (TCP); other values are refused. */
int kinematicsSwitch(int new_type)
{
    if (new_type < 0 || new_type > 1) {
        rtapi_print_msg(RTAPI_MSG_ERR, "kinematicsSwitch:BAD VALUE <%d>\n", new_type);
        return -1;
    }
    active_type = new_type;
    return 0;
}

/* The ops table; its name is filled in from tcpswitch_def at load. */
kins_ops_t kins_ops = { KINS_OPS_VERSION, sizeof(kins_ops_t), "tcpswitch",
    kinematicsType, kinematicsForward, kinematicsInverse, kinematicsSwitchable, kinematicsSwitch };
EXPORT_SYMBOL(kins_ops);
EXPORT_SYMBOL(kinematicsType);
EXPORT_SYMBOL(kinematicsForward);
EXPORT_SYMBOL(kinematicsInverse);
EXPORT_SYMBOL(kinematicsSwitchable);
EXPORT_SYMBOL(kinematicsSwitch);

/* Make `count` float IN pins <prefix>.<names[i]> starting at 0; 0 or negative errno. */
int tcpswitch_float_pins(int owner_id, const char *prefix, const char *const *names,
                         hal_float_t **pins[], int count)
{
    for (int i = 0; i < count; i++) {
        int r = hal_pin_float_newf(HAL_IN, pins[i], owner_id, "%s.%s", prefix, names[i]);
        if (r < 0)
            return r;
        *pins[i][0] = 0.0;
    }
    return 0;
}

/* Register the component, make the pins, start with the identity kinematics. */
int rtapi_app_main(void)
{
    kins_ops.name = tcpswitch_def.name;
    comp_id = hal_init(tcpswitch_def.name);
    if (comp_id < 0)
        return comp_id;
    int r = tcpswitch_def.setup(comp_id, tcpswitch_def.prefix);
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: setup failed (%d)\n", tcpswitch_def.name, r);
        hal_exit(comp_id);
        return r;
    }
    active_type = 0;
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
