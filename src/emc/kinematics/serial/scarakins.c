/* scarakins.c: switchable SCARA kinematics; pins D1..D6 set the arm geometry. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/switchkins.h"
#include "scara_math.h"
#include "emc/kinematics/kins_pins.h"

MODULE_DESCRIPTION("Switchable SCARA kinematics");

enum { SCARA_D1, SCARA_D2, SCARA_D3, SCARA_D4, SCARA_D5, SCARA_D6, SCARA_PINS };

static const kins_pin_def_t scara_pin_defs[SCARA_PINS] = {
    {"D1", 490.0}, {"D2", 340.0}, {"D3", 50.0}, {"D4", 250.0}, {"D5", 50.0}, {"D6", 50.0},
};

static hal_float_t **scara_pins;

/* Current geometry from the pins. */
static scara_params_t scara_params(void)
{
    scara_params_t p;
    p.d1 = *scara_pins[SCARA_D1];
    p.d2 = *scara_pins[SCARA_D2];
    p.d3 = *scara_pins[SCARA_D3];
    p.d4 = *scara_pins[SCARA_D4];
    p.d5 = *scara_pins[SCARA_D5];
    p.d6 = *scara_pins[SCARA_D6];
    return p;
}

/* Joints -> pose. */
static int scara_fwd(const double *joints, EmcPose *pos)
{
    scara_params_t p = scara_params();
    return scara_forward(&p, joints, pos, NULL);
}

/* Pose -> joints, keeping the current elbow side. */
static int scara_inv(const EmcPose *pos, double *joints)
{
    scara_params_t p = scara_params();
    return scara_inverse_keep_elbow(&p, pos, joints);
}

/* Make scarakins.D1 ... scarakins.D6. */
static int scara_setup(int comp_id, const char *sparm)
{
    (void)sparm;
    return kins_float_pins(comp_id, "scarakins", scara_pin_defs, SCARA_PINS, &scara_pins);
}

const switchkins_def_t switchkins_def = {
    .name = "scarakins", .default_coordinates = "XYZCAB", .native_type = KINEMATICS_BOTH,
    .setup = scara_setup, .native_forward = scara_fwd, .native_inverse = scara_inv,
};
