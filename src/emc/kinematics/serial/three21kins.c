/* three21kins.c: switchable kinematics of a 6R arm with a 3-2-1 wrist (LinuxCNC's three21kins). */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "emc/kinematics/kins_pins.h"
#include "three21_math.h"

MODULE_DESCRIPTION("Switchable 3-2-1 (AR2-style) arm kinematics");

/* Link lengths and offsets in the order of three21_params_t. */
static const kins_pin_def_t t21_pin_defs[] = {
    {"A1", 64.2}, {"A2", 305.0}, {"A3", 0.0}, {"D1", 169.77},
    {"D2", 0.0}, {"D3", -6.25}, {"D4", 223.63}, {"D6", 36.5},
};
#define T21_PIN_COUNT ((int)(sizeof(t21_pin_defs) / sizeof(t21_pin_defs[0])))

static hal_float_t **t21_pins;

/* Current geometry from the pins. */
static three21_params_t t21_params(void)
{
    return (three21_params_t){*t21_pins[0], *t21_pins[1], *t21_pins[2], *t21_pins[3],
                              *t21_pins[4], *t21_pins[5], *t21_pins[6], *t21_pins[7]};
}

static int t21_setup(int comp_id, const char *sparm)
{
    (void)sparm;
    return kins_float_pins(comp_id, "three21kins", t21_pin_defs, T21_PIN_COUNT, &t21_pins);
}

static int t21_forward_flags(const double *joints, EmcPose *pos, KINEMATICS_INVERSE_FLAGS *iflags)
{
    three21_params_t p = t21_params();
    return three21_forward(&p, joints, pos, iflags);
}

static int t21_inverse_flags(const EmcPose *pos, double *joints, const KINEMATICS_INVERSE_FLAGS *iflags,
                             KINEMATICS_FORWARD_FLAGS *fflags)
{
    three21_params_t p = t21_params();
    return three21_inverse(&p, pos, iflags ? *iflags : 0, joints, fflags);
}

/* Without flags: forward as above, inverse in the default configuration. */
static int t21_forward(const double *joints, EmcPose *pos)
{
    return t21_forward_flags(joints, pos, NULL);
}

static int t21_inverse(const EmcPose *pos, double *joints)
{
    return t21_inverse_flags(pos, joints, NULL, NULL);
}

const switchkins_def_t switchkins_def = {
    .name = "three21kins", .default_coordinates = "XYZABC", .native_type = KINEMATICS_BOTH,
    .setup = t21_setup, .native_forward = t21_forward, .native_inverse = t21_inverse,
    .native_forward_flags = t21_forward_flags, .native_inverse_flags = t21_inverse_flags,
};
