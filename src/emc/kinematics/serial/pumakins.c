/* pumakins.c: switchable PUMA 560 kinematics; pins A2 A3 D3 D4 D6 set the arm geometry. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "arm6_math.h"
#include "serial_pins.h"

MODULE_DESCRIPTION("Switchable PUMA 560 kinematics");

enum { PUMA_A2, PUMA_A3, PUMA_D3, PUMA_D4, PUMA_D6, PUMA_PINS };

static const serial_pin_def_t puma_pin_defs[PUMA_PINS] = {
    {"A2", 300.0}, {"A3", 50.0}, {"D3", 70.0}, {"D4", 400.0}, {"D6", 70.0},
};

static hal_float_t **puma_pins;

/* Current geometry from the pins. */
static arm6_params_t puma_params(void)
{
    arm6_params_t p = {0};
    p.a2 = *puma_pins[PUMA_A2];
    p.a3 = *puma_pins[PUMA_A3];
    p.d3 = *puma_pins[PUMA_D3];
    p.d4 = *puma_pins[PUMA_D4];
    p.d6 = *puma_pins[PUMA_D6];
    return p;
}

/* Joints -> tool pose. */
static int puma_forward(const double *joints, EmcPose *pos)
{
    arm6_params_t p = puma_params();
    return arm6_forward(&p, joints, pos, NULL);
}

/* Pose -> joints, in the arm configuration nearest to the current joints. */
static int puma_inverse(const EmcPose *pos, double *joints)
{
    arm6_params_t p = puma_params();
    return arm6_inverse_nearest(&p, pos, joints);
}

/* Make pumakins.A2 ... pumakins.D6. */
static int puma_setup(int comp_id, const char *sparm)
{
    (void)sparm;
    puma_pins = hal_malloc(PUMA_PINS * sizeof(*puma_pins));
    if (!puma_pins)
        return -ENOMEM;
    return serial_float_pins(comp_id, "pumakins", puma_pin_defs, PUMA_PINS, puma_pins);
}

const switchkins_def_t switchkins_def = {
    "pumakins", "XYZABC", KINEMATICS_BOTH, puma_setup, puma_forward, puma_inverse, 0,
};
