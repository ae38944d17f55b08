/* switchkins.h: shared frame of switchable kinematics (0 native, 1 identity, 2 user template). */
#ifndef SWITCHKINS_H
#define SWITCHKINS_H

#include "kinematics.h"
#include "kins_coords.h"

/* Forward and inverse of one of the three kinematics a module can switch between. */
typedef int (*switchkins_fwd_fn)(const double *joints, EmcPose *pos);
typedef int (*switchkins_inv_fn)(const EmcPose *pos, double *joints);

/* What a switchable module supplies; switchkins.c does the rest. */
typedef struct switchkins_def {
    const char *name;                /* HAL component name, e.g. "xyzac-trt-kins" */
    const char *default_coordinates; /* identity map used for type 1, e.g. "XYZAC" */
    KINEMATICS_TYPE native_type;     /* type reported while type 0 is active */
    /* Make the module's own pins/params (comp_id ready for hal_*_new); 0 or negative errno. */
    int (*setup)(int comp_id, const char *sparm);
    switchkins_fwd_fn native_forward;
    switchkins_inv_fn native_inverse;
    int identity_first_allowed;      /* sparm=identityfirst swaps types 0 and 1 */
    /* Optional: runs after every successful forward of any type (genhexkins' skgui pins); its
     * non-zero result is returned by kinematicsForward. */
    int (*after_forward)(const double *joints);
    /* Optional: told each time a type is selected (also the type 0 selected at load). */
    void (*on_switch)(int new_type);
    /* Optional flag-aware native kinematics (three21kins' arm configuration); when set they are
     * used instead of native_forward/native_inverse. */
    int (*native_forward_flags)(const double *joints, EmcPose *pos, KINEMATICS_INVERSE_FLAGS *iflags);
    int (*native_inverse_flags)(const EmcPose *pos, double *joints, const KINEMATICS_INVERSE_FLAGS *iflags,
                                KINEMATICS_FORWARD_FLAGS *fflags);
} switchkins_def_t;

/* Each switchable module defines exactly one of these. */
extern const switchkins_def_t switchkins_def;

/* The identity map in use (parsed coordinates=), for modules that need it. */
const kins_coords_t *switchkins_coords(void);

#endif
