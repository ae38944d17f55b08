/* kins_glue.h: the non-switchable kinematics exports shared by the parallel modules. */
#ifndef KINS_GLUE_H
#define KINS_GLUE_H

/* Define kinematicsType (BOTH), the switch stubs and the kins_ops table of module NAME. */
#define KINS_GLUE_BOTH(module_name) \
    KINEMATICS_TYPE kinematicsType(void) { return KINEMATICS_BOTH; } \
    int kinematicsSwitchable(void) { return 0; } \
    int kinematicsSwitch(int switchkins_type) { (void)switchkins_type; return 0; } \
    KINS_EXPORT_OPS(module_name)

#endif
