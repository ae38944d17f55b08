/* pumakins.c: switchable PUMA 560 kinematics; pins A2 A3 D3 D4 D6 set the arm geometry. */
#include "rtapi.h"
#include "emc/kinematics/switchkins.h"
#include "arm6_module.h"

MODULE_DESCRIPTION("Switchable PUMA 560 kinematics");

static const kins_pin_def_t puma_pin_defs[] = {
    {"A2", 300.0}, {"A3", 50.0}, {"D3", 70.0}, {"D4", 400.0}, {"D6", 70.0},
};
static const size_t puma_members[] = {
    offsetof(arm6_params_t, a2), offsetof(arm6_params_t, a3), offsetof(arm6_params_t, d3),
    offsetof(arm6_params_t, d4), offsetof(arm6_params_t, d6),
};

const arm6_module_t arm6_module = {"pumakins", puma_pin_defs, puma_members,
                                     sizeof(puma_members) / sizeof(puma_members[0])};

const switchkins_def_t switchkins_def = {
    .name = "pumakins", .default_coordinates = "XYZABC", .native_type = KINEMATICS_BOTH,
    .setup = arm6_module_setup, .native_forward = arm6_module_forward, .native_inverse = arm6_module_inverse,
};
