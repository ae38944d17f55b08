/* trsrn.h: the module glue shared by xyzacb_trsrn and xyzbca_trsrn (types 0 identity, 1 TCP, 2 TOOL). */
#ifndef FIVEAXIS_TRSRN_H
#define FIVEAXIS_TRSRN_H

#include "emc/kinematics/kinematics.h"
#include "trsrn_math.h"

/* Which machine and the names its pins use. */
typedef struct {
    trsrn_variant_t variant;
    const char *pin_prefix;   /* "xyzacb_trsrn_kins" */
    const char *pivot_pin;    /* "y-pivot" or "x-pivot" */
    const char *rot_axis_pin; /* "y-rot-axis" or "x-rot-axis" */
} trsrn_module_t;

/* Load-time pin of one instance: <prefix>.dummy (s32 OUT). */
int trsrn_instance(int comp_id, int i, const char *prefix);
/* The kinematics pins of module m (first type query); 0 or -errno. */
int trsrn_setup_pins(int comp_id, const trsrn_module_t *m);
/* Forward and inverse of type t for module m. */
int trsrn_forward(const trsrn_module_t *m, int t, const double *joints, EmcPose *pos);
int trsrn_inverse(const trsrn_module_t *m, int t, const EmcPose *pos, double *joints);

#endif
