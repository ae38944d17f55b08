/* xyzac_trt_kins.c: xyzac-trt-kins, switchable kinematics of a tilting (A) table carrying a rotary (C). */
#include "rtapi.h"
#include "emc/kinematics/switchkins.h"
#include "rotary_math.h"
#include "trtkins.h"

MODULE_DESCRIPTION("Switchable kinematics for a trunnion table: tilt A (about X) carrying rotary C");

const trtkins_variant_t trtkins_variant = {"xyzac-trt-kins", "XYZAC", ROT_X, 3};

const switchkins_def_t switchkins_def = {
    .name = "xyzac-trt-kins", .default_coordinates = "XYZAC", .native_type = KINEMATICS_BOTH,
    .setup = trtkins_setup, .native_forward = trtkins_forward, .native_inverse = trtkins_inverse,
    .identity_first_allowed = 1,
};
