/* kinematics.h: the kinematics module interface, under the names LinuxCNC modules export. */
#ifndef KINEMATICS_H
#define KINEMATICS_H

#include "kins_ops.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Joint positions -> world pose; non-zero when the joints have no pose. */
extern int kinematicsForward(const double *joint, EmcPose *world,
                             const KINEMATICS_FORWARD_FLAGS *fflags,
                             KINEMATICS_INVERSE_FLAGS *iflags);
/* World pose -> joint positions; non-zero aborts motion. */
extern int kinematicsInverse(const EmcPose *world, double *joint,
                             const KINEMATICS_INVERSE_FLAGS *iflags,
                             KINEMATICS_FORWARD_FLAGS *fflags);
/* Which of forward/inverse the module can do. */
extern KINEMATICS_TYPE kinematicsType(void);
/* Non-zero when kinematicsSwitch can change the active kinematics. */
extern int kinematicsSwitchable(void);
/* Select kinematics 0 (native), 1 (identity) or 2 (user); 0 or non-zero on a bad value. */
extern int kinematicsSwitch(int switchkins_type);

/* Define the module's kins_ops table from the five functions above and export all of them. */
#define KINS_EXPORT_OPS(module_name) \
    const kins_ops_t kins_ops = { KINS_OPS_VERSION, sizeof(kins_ops_t), module_name, \
        kinematicsType, kinematicsForward, kinematicsInverse, \
        kinematicsSwitchable, kinematicsSwitch }; \
    EXPORT_SYMBOL(kins_ops); \
    EXPORT_SYMBOL(kinematicsType); \
    EXPORT_SYMBOL(kinematicsForward); \
    EXPORT_SYMBOL(kinematicsInverse); \
    EXPORT_SYMBOL(kinematicsSwitchable); \
    EXPORT_SYMBOL(kinematicsSwitch)

/* For modules written against LinuxCNC's header: stubs for kinematics that cannot switch. */
#define KINS_NOT_SWITCHABLE \
    int kinematicsSwitchable(void) { return 0; } \
    int kinematicsSwitch(int switchkins_type) { (void)switchkins_type; return 0; } \
    EXPORT_SYMBOL(kinematicsSwitchable); \
    EXPORT_SYMBOL(kinematicsSwitch);

#ifdef __cplusplus
}
#endif

#endif
