/* xyzbc_trt_kins.c: xyzbc-trt-kins, switchable kinematics of a tilting (B) table carrying a rotary (C). */
#include "rtapi.h"
#include "emc/kinematics/switchkins.h"
#include "rotary_math.h"
#include "trtkins.h"

MODULE_DESCRIPTION("Switchable kinematics for a trunnion table: tilt B (about Y) carrying rotary C");

const trtkins_variant_t trtkins_variant = {"xyzbc-trt-kins", "XYZBC", ROT_Y, 4};

const switchkins_def_t switchkins_def = {
    .name = "xyzbc-trt-kins", .default_coordinates = "XYZBC", .native_type = KINEMATICS_BOTH,
    .setup = trtkins_setup, .native_forward = trtkins_forward, .native_inverse = trtkins_inverse,
    .identity_first_allowed = 1,
};
