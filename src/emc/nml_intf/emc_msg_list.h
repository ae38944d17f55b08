/* emc_msg_list.h: every NML message of OpenEMC as one list (name, LinuxCNC type number, group). */
#ifndef EMC_MSG_LIST_H
#define EMC_MSG_LIST_H

/* X(NAME, NUMBER) for every message class; NAME is the C++ class and, with _TYPE
 * appended, the type constant (nml.md sec. 3). Everything that needs one entry per
 * message (type enum, size table, symbol lookup, tests) is generated from this list. */
#define EMC_MSG_LIST(X)                                   \
    X(NML_ERROR, 1)                                       \
    X(NML_TEXT, 2)                                        \
    X(NML_DISPLAY, 3)                                     \
    X(EMC_OPERATOR_ERROR, 11)                             \
    X(EMC_OPERATOR_TEXT, 12)                              \
    X(EMC_OPERATOR_DISPLAY, 13)                           \
    X(EMC_NULL, 21)                                       \
    X(EMC_SET_DEBUG, 22)                                  \
    X(EMC_SYSTEM_CMD, 30)                                 \
    X(EMC_JOINT_SET_MIN_POSITION_LIMIT, 107)              \
    X(EMC_JOINT_SET_MAX_POSITION_LIMIT, 108)              \
    X(EMC_JOINT_SET_FERROR, 111)                          \
    X(EMC_JOINT_SET_HOMING_PARAMS, 112)                   \
    X(EMC_JOINT_SET_MIN_FERROR, 115)                      \
    X(EMC_JOINT_HALT, 119)                                \
    X(EMC_JOINT_HOME, 123)                                \
    X(EMC_JOG_CONT, 124)                                  \
    X(EMC_JOG_INCR, 125)                                  \
    X(EMC_JOG_ABS, 126)                                   \
    X(EMC_JOINT_OVERRIDE_LIMITS, 129)                     \
    X(EMC_JOINT_LOAD_COMP, 131)                           \
    X(EMC_JOINT_SET_BACKLASH, 134)                        \
    X(EMC_JOINT_UNHOME, 135)                              \
    X(EMC_JOG_STOP, 136)                                  \
    X(EMC_JOINT_STAT, 198)                                \
    X(EMC_AXIS_STAT, 199)                                 \
    X(EMC_TRAJ_SET_MODE, 204)                             \
    X(EMC_TRAJ_SET_VELOCITY, 205)                         \
    X(EMC_TRAJ_SET_ACCELERATION, 206)                     \
    X(EMC_TRAJ_SET_MAX_VELOCITY, 207)                     \
    X(EMC_TRAJ_SET_SCALE, 209)                            \
    X(EMC_TRAJ_ABORT, 215)                                \
    X(EMC_TRAJ_PAUSE, 216)                                \
    X(EMC_TRAJ_RESUME, 218)                               \
    X(EMC_TRAJ_DELAY, 219)                                \
    X(EMC_TRAJ_LINEAR_MOVE, 220)                          \
    X(EMC_TRAJ_CIRCULAR_MOVE, 221)                        \
    X(EMC_TRAJ_SET_TERM_COND, 222)                        \
    X(EMC_TRAJ_SET_OFFSET, 223)                           \
    X(EMC_TRAJ_SET_G5X, 224)                              \
    X(EMC_TRAJ_SET_ROTATION, 226)                         \
    X(EMC_TRAJ_SET_G92, 227)                              \
    X(EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG, 228)             \
    X(EMC_TRAJ_PROBE, 229)                                \
    X(EMC_TRAJ_SET_TELEOP_ENABLE, 230)                    \
    X(EMC_TRAJ_SET_SPINDLESYNC, 232)                      \
    X(EMC_TRAJ_SET_SPINDLE_SCALE, 233)                    \
    X(EMC_TRAJ_SET_FO_ENABLE, 234)                        \
    X(EMC_TRAJ_SET_SO_ENABLE, 235)                        \
    X(EMC_TRAJ_SET_FH_ENABLE, 236)                        \
    X(EMC_TRAJ_RIGID_TAP, 237)                            \
    X(EMC_TRAJ_SET_RAPID_SCALE, 238)                      \
    X(EMC_TRAJ_STAT, 299)                                 \
    X(EMC_MOTION_SET_AOUT, 304)                           \
    X(EMC_MOTION_SET_DOUT, 305)                           \
    X(EMC_MOTION_ADAPTIVE, 306)                           \
    X(EMC_MOTION_STAT, 399)                               \
    X(EMC_TASK_ABORT, 503)                                \
    X(EMC_TASK_SET_MODE, 504)                             \
    X(EMC_TASK_SET_STATE, 505)                            \
    X(EMC_TASK_PLAN_OPEN, 506)                            \
    X(EMC_TASK_PLAN_RUN, 507)                             \
    X(EMC_TASK_PLAN_EXECUTE, 509)                         \
    X(EMC_TASK_PLAN_PAUSE, 510)                           \
    X(EMC_TASK_PLAN_STEP, 511)                            \
    X(EMC_TASK_PLAN_RESUME, 512)                          \
    X(EMC_TASK_PLAN_END, 513)                             \
    X(EMC_TASK_PLAN_CLOSE, 514)                           \
    X(EMC_TASK_PLAN_INIT, 515)                            \
    X(EMC_TASK_PLAN_SYNCH, 516)                           \
    X(EMC_TASK_PLAN_SET_OPTIONAL_STOP, 517)               \
    X(EMC_TASK_PLAN_SET_BLOCK_DELETE, 518)                \
    X(EMC_TASK_PLAN_OPTIONAL_STOP, 519)                   \
    X(EMC_TASK_PLAN_REVERSE, 520)                         \
    X(EMC_TASK_PLAN_FORWARD, 521)                         \
    X(EMC_TASK_STAT, 599)                                 \
    X(EMC_TOOL_HALT, 1102)                                \
    X(EMC_TOOL_ABORT, 1103)                               \
    X(EMC_TOOL_PREPARE, 1104)                             \
    X(EMC_TOOL_LOAD, 1105)                                \
    X(EMC_TOOL_UNLOAD, 1106)                              \
    X(EMC_TOOL_LOAD_TOOL_TABLE, 1107)                     \
    X(EMC_TOOL_SET_OFFSET, 1108)                          \
    X(EMC_TOOL_SET_NUMBER, 1109)                          \
    X(EMC_TOOL_STAT, 1199)                                \
    X(EMC_AUX_INPUT_WAIT, 1209)                           \
    X(EMC_AUX_STAT, 1299)                                 \
    X(EMC_SPINDLE_ON, 1304)                               \
    X(EMC_SPINDLE_OFF, 1305)                              \
    X(EMC_SPINDLE_INCREASE, 1309)                         \
    X(EMC_SPINDLE_DECREASE, 1310)                         \
    X(EMC_SPINDLE_CONSTANT, 1311)                         \
    X(EMC_SPINDLE_BRAKE_RELEASE, 1312)                    \
    X(EMC_SPINDLE_BRAKE_ENGAGE, 1313)                     \
    X(EMC_SPINDLE_SPEED, 1316)                            \
    X(EMC_SPINDLE_ORIENT, 1317)                           \
    X(EMC_SPINDLE_WAIT_ORIENT_COMPLETE, 1318)             \
    X(EMC_SPINDLE_STAT, 1399)                             \
    X(EMC_COOLANT_MIST_ON, 1404)                          \
    X(EMC_COOLANT_MIST_OFF, 1405)                         \
    X(EMC_COOLANT_FLOOD_ON, 1406)                         \
    X(EMC_COOLANT_FLOOD_OFF, 1407)                        \
    X(EMC_COOLANT_STAT, 1499)                             \
    X(EMC_IO_STAT, 1699)                                  \
    X(EMC_STAT, 1999)

/* NMLTYPE constants: EMC_TASK_SET_MODE_TYPE = 504, ... */
#define EMC_MSG_TYPE_ENUMERATOR(name, number) name##_TYPE = number,
enum emc_msg_type { EMC_MSG_LIST(EMC_MSG_TYPE_ENUMERATOR) };
#undef EMC_MSG_TYPE_ENUMERATOR

#endif
