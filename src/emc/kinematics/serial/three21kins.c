/* three21kins.c: switchable kinematics of a 6R arm with shoulder offset and spherical wrist. */
#include "rtapi.h"
#include "emc/kinematics/switchkins.h"
#include "arm6_module.h"

MODULE_DESCRIPTION("Switchable 3-2-1 (offset shoulder, spherical wrist) arm kinematics");

static const kins_pin_def_t t21_pin_defs[] = {
    {"A1", 0.0}, {"A2", 300.0}, {"A3", 50.0}, {"D1", 0.0},
    {"D2", 0.0}, {"D3", 70.0}, {"D4", 400.0}, {"D6", 70.0},
};
static const size_t t21_members[] = {
    offsetof(arm6_params_t, a1), offsetof(arm6_params_t, a2), offsetof(arm6_params_t, a3),
    offsetof(arm6_params_t, d1), offsetof(arm6_params_t, d2), offsetof(arm6_params_t, d3),
    offsetof(arm6_params_t, d4), offsetof(arm6_params_t, d6),
};

const arm6_module_t arm6_module = {"three21kins", t21_pin_defs, t21_members,
                                     sizeof(t21_members) / sizeof(t21_members[0])};

const switchkins_def_t switchkins_def = {
    "three21kins", "XYZABC", KINEMATICS_BOTH, arm6_module_setup, arm6_module_forward,
    arm6_module_inverse, 0, NULL, NULL,
};
