/* tcpswitch.c: entry points and exports of the TCP kinematics (0 identity, 1 tool center point). */
#include <string.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kins_entry.h"
#include "emc/kinematics/kins_coords.h"
#include "tcpswitch.h"

#define TCPSWITCH_MAX_JOINTS 9

static int active_type;   /* 0 identity, 1 TCP */

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

/* 0 (identity) or 1 (TCP) was selected (kins_entry checked it). */
static void switched(int new_type)
{
    active_type = new_type;
}

/* Make the module's pins and start with the identity kinematics. */
static int tcpswitch_build(int comp_id)
{
    int r = tcpswitch_def.setup(comp_id, tcpswitch_def.prefix);
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: setup failed (%d)\n", tcpswitch_def.name, r);
        return r;
    }
    active_type = 0;
    return 0;
}

/* Register the component, make the pins, start with the identity kinematics. */
int rtapi_app_main(void)
{
    kins_entry_t entry = {tcpswitch_def.name, tcpswitch_build, 1, switched};
    return kins_entry_start(&entry);
}
