component userkins "Template for user-built kinematics";
pin out s32 fwd_calls "Number of kinematicsForward calls (demo pin)";
pin out s32 inv_calls "Number of kinematicsInverse calls (demo pin)";
pin in float z_offset = 0.0 "Demo geometry: forward adds it to Z, inverse takes it off joint 2";
option singleton yes;
option rtapi_app no;
license "GPL";
author "OpenEMC";
description """A starting point for custom kinematics: copy this file, replace the two
transformation functions and build it with "halcompile --install userkins.comp".

As shipped it maps joints 0..8 to X Y Z A B C U V W one to one, except that Z is
joint 2 plus z-offset. It is of type KINEMATICS_BOTH and cannot switch (it
uses KINS_NOT_SWITCHABLE). It exports kinematicsType, kinematicsForward,
kinematicsInverse, kinematicsSwitchable, kinematicsSwitch and the versioned
kins_ops table motion looks up.

The module has no functions; motion calls the kinematics directly.""";
;;
#include "kinematics.h"

/* The single instance, whose pins the kinematics functions read and write. */
#define USERKINS_INST struct __comp_state *__comp_inst = __comp_first_inst

/* Joints -> world: one to one, Z raised by z-offset. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    USERKINS_INST;
    (void)fflags;
    (void)iflags;
    world->tran.x = joint[0];
    world->tran.y = joint[1];
    world->tran.z = joint[2] + z_offset;
    world->a = joint[3];
    world->b = joint[4];
    world->c = joint[5];
    world->u = joint[6];
    world->v = joint[7];
    world->w = joint[8];
    fwd_calls++;
    return 0;
}

/* World -> joints: one to one, z-offset taken off joint 2. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    USERKINS_INST;
    (void)iflags;
    (void)fflags;
    joint[0] = world->tran.x;
    joint[1] = world->tran.y;
    joint[2] = world->tran.z - z_offset;
    joint[3] = world->a;
    joint[4] = world->b;
    joint[5] = world->c;
    joint[6] = world->u;
    joint[7] = world->v;
    joint[8] = world->w;
    inv_calls++;
    return 0;
}

/* Both directions are available. */
KINEMATICS_TYPE kinematicsType(void)
{
    return KINEMATICS_BOTH;
}

KINS_NOT_SWITCHABLE
KINS_EXPORT_OPS("userkins");

/* Create the component and its pins. */
int rtapi_app_main(void)
{
    comp_id = hal_init("userkins");
    if (comp_id < 0)
        return comp_id;
    int r = export("userkins", 0);
    if (r) {
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
