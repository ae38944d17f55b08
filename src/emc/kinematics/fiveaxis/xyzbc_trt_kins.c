/* xyzbc_trt_kins.c: xyzbc-trt-kins, switchable kinematics of a tilting (B) table carrying a rotary (C). */
#include "rtapi.h"
#include "emc/kinematics/switchkins.h"
#include "rotary_math.h"
#include "trtkins.h"

MODULE_DESCRIPTION("Switchable kinematics for a trunnion table: tilt B (about Y) carrying rotary C");

const trtkins_variant_t trtkins_variant = {"xyzbc-trt-kins", "XYZBC", ROT_Y, 4};

const switchkins_def_t switchkins_def = {
    "xyzbc-trt-kins", "XYZBC", KINEMATICS_BOTH, trtkins_setup, trtkins_forward, trtkins_inverse, 1, NULL, NULL,
};
