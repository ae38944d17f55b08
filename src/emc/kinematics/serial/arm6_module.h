/* arm6_module.h: HAL glue of the 6R spherical-wrist arm module pumakins (geometry pins from a table). */
#ifndef ARM6_MODULE_H
#define ARM6_MODULE_H

#include <stddef.h>
#include "emc/kinematics/kins_pins.h"
#include "arm6_math.h"

/* What differs between the arm modules: the geometry pins and the arm6_params_t member each fills. */
typedef struct {
    const char *prefix;           /* pin prefix, e.g. "pumakins" */
    const kins_pin_def_t *pins;   /* geometry pins with their defaults */
    const size_t *members;        /* offsetof(arm6_params_t, ...) of each pin */
    int count;                    /* number of pins; unlisted members are 0 */
} arm6_module_t;

/* Each arm module defines exactly one of these. */
extern const arm6_module_t arm6_module;

/* Switchable-frame setup: make the geometry pins; 0 or negative errno. */
int arm6_module_setup(int comp_id, const char *sparm);
/* Joints -> tool pose through the pins' geometry. */
int arm6_module_forward(const double *joints, EmcPose *pos);
/* Pose -> joints, in the arm configuration nearest to the current joints. */
int arm6_module_inverse(const EmcPose *pos, double *joints);

#endif
