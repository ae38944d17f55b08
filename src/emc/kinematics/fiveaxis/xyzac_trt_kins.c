/* xyzac_trt_kins.c: xyzac-trt-kins, switchable kinematics of a tilting (A) table carrying a rotary (C). */
#include "rtapi.h"
#include "emc/kinematics/switchkins.h"
#include "rotary_math.h"
#include "trtkins.h"

MODULE_DESCRIPTION("Switchable kinematics for a trunnion table: tilt A (about X) carrying rotary C");

static const trtkins_variant_t variant = {"xyzac-trt-kins", "XYZAC", ROT_X, 3};

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
    "xyzac-trt-kins", "XYZAC", KINEMATICS_BOTH, setup, forward, inverse, 1
};
