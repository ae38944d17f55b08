/* kins_ops.h: the versioned table of functions every kinematics module exports as `kins_ops`. */
#ifndef KINS_OPS_H
#define KINS_OPS_H

#include <stddef.h>
#include "emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Kinematics types (motion.md sec. 10 numbering). */
typedef enum {
    KINEMATICS_IDENTITY = 1,
    KINEMATICS_FORWARD_ONLY = 2,
    KINEMATICS_INVERSE_ONLY = 3,
    KINEMATICS_BOTH = 4
} KINEMATICS_TYPE;

typedef unsigned long KINEMATICS_FORWARD_FLAGS;
typedef unsigned long KINEMATICS_INVERSE_FLAGS;

/* Largest joint count motion hands to a kinematics module. */
#define KINS_MAX_JOINTS 16

/* Bump when a member is added, removed or changes meaning. */
#define KINS_OPS_VERSION 1u

/* What motmod calls each servo cycle (forward/inverse) and at start-up. */
typedef struct kins_ops {
    unsigned int version;   /* KINS_OPS_VERSION the module was built with */
    unsigned int size;      /* sizeof(kins_ops_t) the module was built with */
    const char *name;       /* module name, for messages */
    KINEMATICS_TYPE (*type)(void);
    int (*forward)(const double *joints, EmcPose *pos,
                   const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags);
    int (*inverse)(const EmcPose *pos, double *joints,
                   const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags);
    int (*switchable)(void);
    int (*switch_type)(int new_type);
} kins_ops_t;

/* Check a table found in a module; 0, or -EPROTO/-EINVAL with the reason in why. */
int kins_ops_check(const kins_ops_t *ops, char *why, size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
