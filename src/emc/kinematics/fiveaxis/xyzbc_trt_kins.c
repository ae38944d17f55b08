/* xyzbc_trt_kins.c: xyzbc-trt-kins, switchable kinematics of a tilting (B) table carrying a rotary (C). */
#include "rtapi.h"
#include "emc/kinematics/switchkins.h"
#include "rotary_math.h"
#include "trtkins.h"

MODULE_DESCRIPTION("Switchable kinematics for a trunnion table: tilt B (about Y) carrying rotary C");

static const trtkins_variant_t variant = {"xyzbc-trt-kins", "XYZBC", ROT_Y, 4};

/* Pins and coordinates check. */
static int setup(int comp_id, const char *sparm)
{
    (void)sparm;
    return trtkins_setup(&variant, comp_id);
}

/* Native forward. */
static int forward(const double *joints, EmcPose *pos)
{
    return trtkins_forward(&variant, joints, pos);
}

/* Native inverse. */
static int inverse(const EmcPose *pos, double *joints)
{
    return trtkins_inverse(&variant, pos, joints);
}

const switchkins_def_t switchkins_def = {
    "xyzbc-trt-kins", "XYZBC", KINEMATICS_BOTH, setup, forward, inverse, 1
};
