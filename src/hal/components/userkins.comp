component userkins "Template for user-built kinematics (LinuxCNC's userkins)";
pin out s32 fpin "Demonstration pin: counts the calls of fdemo";
function fdemo "Demonstration function: says so once when first run";
license "GPL";
author "OpenEMC";
description """A starting point for custom kinematics: copy this file, rename it (the component name and
the "userkins" strings), replace the two transformation functions and build it with
"halcompile --install mykins.comp"; then name it in [KINS]KINEMATICS.

As shipped it maps joints 0..8 to X Y Z A B C U V W one to one, is of type KINEMATICS_BOTH
and cannot switch. The first time motion asks for the kinematics type it makes the
demonstration pins \\fBuserkins.in\\fR (u32 in) and \\fBuserkins.out\\fR (u32 out); every
inverse call copies in to out. It exports kinematicsType, kinematicsForward,
kinematicsInverse, kinematicsSwitchable, kinematicsSwitch and the versioned kins_ops table
motion looks up.""";
;;
#include "kinematics.h"

#define USERKINS_NAME "userkins"

/* The demonstration pins, made at the first type query (pin pointers must live in HAL memory). */
typedef struct {
    hal_u32_t *in, *out;
} userkins_echo_t;

static userkins_echo_t *echo;
static int inverse_seen, warned;

/* Demonstration function: announce itself once, then count its calls on fpin. */
FUNCTION(fdemo)
{
    (void)period;
    if (fpin == 0)
        rtapi_print_msg(RTAPI_MSG_INFO, "fdemo function added to thread\n");
    fpin++;
}

/* Joints -> world: one to one. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    (void)fflags;
    (void)iflags;
    if (echo && *echo->in && !inverse_seen && !warned) {
        rtapi_print_msg(RTAPI_MSG_INFO, USERKINS_NAME " the 'in' pin not echoed until Inverse called\n");
        warned = 1;
    }
    world->tran.x = joint[0];
    world->tran.y = joint[1];
    world->tran.z = joint[2];
    world->a = joint[3];
    world->b = joint[4];
    world->c = joint[5];
    world->u = joint[6];
    world->v = joint[7];
    world->w = joint[8];
    return 0;
}

/* World -> joints: one to one; the demonstration in pin is copied to out. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    (void)iflags;
    (void)fflags;
    inverse_seen = 1;
    if (echo)
        *echo->out = *echo->in;
    joint[0] = world->tran.x;
    joint[1] = world->tran.y;
    joint[2] = world->tran.z;
    joint[3] = world->a;
    joint[4] = world->b;
    joint[5] = world->c;
    joint[6] = world->u;
    joint[7] = world->v;
    joint[8] = world->w;
    return 0;
}

/* Both directions are available; the first call makes the demonstration pins. */
KINEMATICS_TYPE kinematicsType(void)
{
    static int set_up;
    if (!set_up) {
        userkins_echo_t *e = hal_malloc(sizeof(*e));
        int r = e ? hal_unready(comp_id) : -ENOMEM;
        if (r == 0) r = hal_pin_u32_newf(HAL_IN, &e->in, comp_id, USERKINS_NAME ".in");
        if (r == 0) r = hal_pin_u32_newf(HAL_OUT, &e->out, comp_id, USERKINS_NAME ".out");
        if (e)
            hal_ready(comp_id);
        if (r == 0)
            echo = e;
        if (r)
            rtapi_print_msg(RTAPI_MSG_ERR, "!!! " USERKINS_NAME " setup failed res=%d\n", r);
        set_up = 1;
    }
    return KINEMATICS_BOTH;
}

KINS_NOT_SWITCHABLE
KINS_EXPORT_OPS(USERKINS_NAME);
