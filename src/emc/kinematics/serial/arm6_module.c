/* arm6_module.c: HAL glue of the 6R spherical-wrist arm module pumakins. */
#include "rtapi.h"
#include "hal.h"
#include "arm6_module.h"

static hal_float_t **arm6_pins;

/* Current geometry: every listed member from its pin, the rest 0. */
static arm6_params_t arm6_module_params(void)
{
    arm6_params_t p = {0};
    for (int i = 0; i < arm6_module.count; i++)
        *(double *)((char *)&p + arm6_module.members[i]) = *arm6_pins[i];
    return p;
}

/* Switchable-frame setup: make the geometry pins; 0 or negative errno. */
int arm6_module_setup(int comp_id, const char *sparm)
{
    (void)sparm;
    return kins_float_pins(comp_id, arm6_module.prefix, arm6_module.pins, arm6_module.count,
                           &arm6_pins);
}

/* Joints -> tool pose through the pins' geometry. */
int arm6_module_forward(const double *joints, EmcPose *pos)
{
    arm6_params_t p = arm6_module_params();
    return arm6_forward(&p, joints, pos, NULL);
}

/* Pose -> joints, in the arm configuration nearest to the current joints. */
int arm6_module_inverse(const EmcPose *pos, double *joints)
{
    arm6_params_t p = arm6_module_params();
    return arm6_inverse_nearest(&p, pos, joints);
}
