/* kins_template.h: frame of LinuxCNC's halcompile-style kinematics (matrixkins, xyzacb_trsrn,
 * xyzbca_trsrn, xyzab_tdr_kins, millturn, userkins): count=/names= instances with load-time pins, the
 * kinematics pins made at the first type query, and their own switching (kinstype.is-N). */
#ifndef KINS_TEMPLATE_H
#define KINS_TEMPLATE_H

#include "kinematics.h"

#define KINS_TEMPLATE_MAX_TYPES 3

/* What a module supplies; kins_template.c provides the entry points and exports. */
typedef struct kins_template_def {
    const char *name;         /* HAL component name, e.g. "xyzacb_trsrn" */
    const char *inst_prefix;  /* instance prefix base of the load-time pins, e.g. "xyzacb-trsrn" */
    /* Load-time pins and functs of instance i named prefix; 0 or -errno. */
    int (*instance)(int comp_id, int i, const char *prefix);
    /* The kinematics pins, made once at the first kinematicsType call; 0 or -errno. */
    int (*setup)(int comp_id);
    int ntypes;               /* 1: fixed kinematics; 2 or 3: switchable, kinstype.is-0..ntypes-1 */
    /* Joints -> world and world -> joints for kinematics type t (0..ntypes-1). */
    int (*forward)(int t, const double *joints, EmcPose *pos);
    int (*inverse)(int t, const EmcPose *pos, double *joints);
} kins_template_def_t;

/* Each module defines exactly one of these. */
extern const kins_template_def_t kins_template_def;

#endif
