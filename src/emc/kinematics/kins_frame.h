/* kins_frame.h: shared frame of non-switchable kinematics (the counterpart of switchkins.h). */
#ifndef KINS_FRAME_H
#define KINS_FRAME_H

#include "kinematics.h"

/* What a non-switchable module supplies; kins_frame.c provides entry points and exports. */
typedef struct kins_frame_def {
    const char *name;         /* HAL component name, e.g. "trivkins" */
    KINEMATICS_TYPE type;     /* reported by kinematicsType unless check changes it */
    /* Optional, before the component exists: parse module params, may change *type; 0 or -errno. */
    int (*check)(KINEMATICS_TYPE *type);
    /* Optional, once comp_id is ready: make pins/params; 0 or -errno. */
    int (*setup)(int comp_id);
    const char *setup_error;  /* when set, a failed setup prints "<name>: ERROR: <this>" */
    /* Joints -> world and world -> joints; non-zero when there is no solution. */
    int (*forward)(const double *joints, EmcPose *pos);
    int (*inverse)(const EmcPose *pos, double *joints);
    /* Optional: used instead of forward/inverse by modules that read or set the flags. */
    int (*forward_flags)(const double *joints, EmcPose *pos,
                         const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags);
    int (*inverse_flags)(const EmcPose *pos, double *joints,
                         const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags);
} kins_frame_def_t;

/* Each non-switchable module defines exactly one of these (designated initializers). */
extern const kins_frame_def_t kins_frame_def;

#endif
