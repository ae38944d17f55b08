/* three21kins.c: switchable kinematics of a 6R arm with shoulder offset and spherical wrist. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "arm6_math.h"
#include "serial_pins.h"

MODULE_DESCRIPTION("Switchable 3-2-1 (offset shoulder, spherical wrist) arm kinematics");

enum { T21_A1, T21_A2, T21_A3, T21_D1, T21_D2, T21_D3, T21_D4, T21_D6, T21_PINS };

static const serial_pin_def_t t21_pin_defs[T21_PINS] = {
    {"A1", 0.0}, {"A2", 300.0}, {"A3", 50.0}, {"D1", 0.0},
    {"D2", 0.0}, {"D3", 70.0}, {"D4", 400.0}, {"D6", 70.0},
};

static hal_float_t **t21_pins;

/* Current geometry from the pins. */
static arm6_params_t t21_params(void)
{
    arm6_params_t p;
    p.a1 = *t21_pins[T21_A1];
    p.a2 = *t21_pins[T21_A2];
    p.a3 = *t21_pins[T21_A3];
    p.d1 = *t21_pins[T21_D1];
    p.d2 = *t21_pins[T21_D2];
    p.d3 = *t21_pins[T21_D3];
    p.d4 = *t21_pins[T21_D4];
    p.d6 = *t21_pins[T21_D6];
    return p;
}

/* Joints -> tool pose. */
static int t21_forward(const double *joints, EmcPose *pos)
{
    arm6_params_t p = t21_params();
    return arm6_forward(&p, joints, pos, NULL);
}

/* Pose -> joints, in the arm configuration nearest to the current joints. */
static int t21_inverse(const EmcPose *pos, double *joints)
{
    arm6_params_t p = t21_params();
    return arm6_inverse_nearest(&p, pos, joints);
}

/* Make three21kins.A1 ... three21kins.D6. */
static int t21_setup(int comp_id, const char *sparm)
{
    (void)sparm;
    t21_pins = hal_malloc(T21_PINS * sizeof(*t21_pins));
    if (!t21_pins)
        return -ENOMEM;
    return serial_float_pins(comp_id, "three21kins", t21_pin_defs, T21_PINS, t21_pins);
}

const switchkins_def_t switchkins_def = {
    "three21kins", "XYZABC", KINEMATICS_BOTH, t21_setup, t21_forward, t21_inverse, 0,
};
