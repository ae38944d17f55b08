// emc_stat.hh: the status structure EMC_STAT task writes to emcStatus every cycle (nml.md sec. 5).
#ifndef EMC_STAT_HH
#define EMC_STAT_HH

#include "emcpos.h"
#include "nml_base.hh"
#include "state_tag.h"
#include "tooldata.h"

// Flags are uint8_t (0/1), never bool: a status copied from shared memory must not be
// able to hold an invalid bool.

struct EMC_TASK_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_TASK_STAT, RCS_STAT_MSG)
    int32_t mode = EMC_TASK_MODE_MANUAL;
    int32_t state = EMC_TASK_STATE_ESTOP;  // emc_task_state
    int32_t execState = EMC_TASK_EXEC_DONE;
    int32_t interpState = EMC_TASK_INTERP_IDLE;
    int32_t callLevel = 0;
    int32_t motionLine = 0;
    int32_t currentLine = 0;
    int32_t readLine = 0;
    uint8_t optional_stop_state = 1;
    uint8_t block_delete_state = 1;
    uint8_t input_timeout = 0;
    char file[LINELEN] = {};
    char command[LINELEN] = {};
    char ini_filename[LINELEN] = {};
    EmcPose g5x_offset = {};
    int32_t g5x_index = 1;
    EmcPose g92_offset = {};
    double rotation_xy = 0;
    EmcPose toolOffset = {};
    int32_t activeGCodes[STATE_TAG_GCODES] = {};
    int32_t activeMCodes[STATE_TAG_MCODES] = {};
    double activeSettings[STATE_TAG_SETTINGS] = {};
    int32_t programUnits = 0;  // 1 in, 2 mm, 3 cm
    int32_t interpreter_errcode = 0;
    int32_t task_paused = 0;
    double delayLeft = 0;
    int32_t queuedMDIcommands = 0;
    uint64_t taskbeat = 0;  // task cycles
};

struct EMC_TRAJ_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_TRAJ_STAT, RCS_STAT_MSG)
    double linearUnits = 0;   // machine units per mm
    double angularUnits = 0;  // machine units per degree
    double cycleTime = 0;     // servo period, s
    int32_t joints = 0;
    int32_t spindles = 0;
    int32_t axis_mask = 0;    // X=1 Y=2 Z=4 A=8 B=16 C=32 U=64 V=128 W=256
    int32_t mode = EMC_TRAJ_MODE_FREE;
    uint8_t enabled = 0;
    uint8_t inpos = 1;
    uint8_t queueFull = 0;
    uint8_t paused = 0;
    uint8_t single_stepping = 0;
    uint8_t probe_tripped = 0;
    uint8_t probing = 0;
    uint8_t feed_override_enabled = 1;
    uint8_t adaptive_feed_enabled = 0;
    uint8_t feed_hold_enabled = 1;
    int32_t queue = 0;
    int32_t activeQueue = 0;
    int32_t id = 0;
    double scale = 1.0;        // feed override
    double rapid_scale = 1.0;  // rapid override
    EmcPose position = {};        // commanded, machine coordinates
    EmcPose actualPosition = {};  // feedback, machine coordinates
    double velocity = 0;
    double acceleration = 0;
    double maxVelocity = 0;
    double maxAcceleration = 0;
    EmcPose probedPosition = {};
    int32_t probeval = 0;
    int32_t kinematics_type = 0;  // emc_kinematics_type
    int32_t motion_type = 0;      // emc_motion_type
    double distance_to_go = 0;
    EmcPose dtg = {};
    double current_vel = 0;
    state_tag_t tag = {};
};

struct EMC_JOINT_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_JOINT_STAT, RCS_STAT_MSG)
    int32_t jointType = EMC_LINEAR;
    double units = 1.0;
    double backlash = 0;
    double minPositionLimit = -1.0;
    double maxPositionLimit = 1.0;
    double maxFerror = 1.0;
    double minFerror = 1.0;
    double ferrorCurrent = 0;
    double ferrorHighMark = 0;
    double output = 0;    // commanded position
    double input = 0;     // feedback position
    double velocity = 0;
    uint8_t inpos = 1;
    uint8_t homing = 0;
    uint8_t homed = 0;
    uint8_t fault = 0;
    uint8_t enabled = 0;
    uint8_t minSoftLimit = 0;
    uint8_t maxSoftLimit = 0;
    uint8_t minHardLimit = 0;
    uint8_t maxHardLimit = 0;
    uint8_t overrideLimits = 0;
};

struct EMC_AXIS_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_AXIS_STAT, RCS_STAT_MSG)
    double minPositionLimit = 0;
    double maxPositionLimit = 0;
    double velocity = 0;
};

struct EMC_SPINDLE_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_SPINDLE_STAT, RCS_STAT_MSG)
    double speed = 0;          // signed rpm (CSS: the maximum)
    double spindle_scale = 1.0;
    double css_maximum = 0;
    double css_factor = 0;
    int32_t state = 0;
    int32_t direction = 0;     // 1 forward, -1 reverse, 0 off
    int32_t brake = 1;         // 1 while stopped
    int32_t increasing = 0;
    int32_t enabled = 0;
    int32_t orient_state = 0;
    int32_t orient_fault = 0;
    uint8_t spindle_override_enabled = 1;
    uint8_t homed = 0;
};

struct EMC_MOTION_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_MOTION_STAT, RCS_STAT_MSG)
    EMC_TRAJ_STAT traj;
    EMC_JOINT_STAT joint[EMCMOT_MAX_JOINTS];
    EMC_AXIS_STAT axis[EMCMOT_MAX_AXIS];
    EMC_SPINDLE_STAT spindle[EMCMOT_MAX_SPINDLES];
    int32_t synch_di[EMCMOT_MAX_DIO] = {};
    int32_t synch_do[EMCMOT_MAX_DIO] = {};
    double analog_input[EMCMOT_MAX_AIO] = {};
    double analog_output[EMCMOT_MAX_AIO] = {};
    int32_t misc_error[EMCMOT_MAX_MISC_ERROR] = {};
    int32_t debug = 0;
    int32_t on_soft_limit = 0;
    int32_t external_offsets_applied = 0;
    EmcPose eoffset_pose = {};
    int32_t numExtraJoints = 0;
    int32_t jogging_active = 0;
    uint64_t heartbeat = 0;  // servo cycles
};

struct EMC_TOOL_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_TOOL_STAT, RCS_STAT_MSG)
    int32_t pocketPrepped = -1;  // tool-table index of the prepared tool, -1 none
    int32_t toolInSpindle = 0;   // tool number, 0 none
    int32_t toolFromPocket = 0;
    // The entry of the tool in the spindle. The whole table is published through
    // tooldata.h (not in this structure), like LinuxCNC's tool mmap.
    tooldata_entry_t toolTableCurrent = {-1, 0, {}, 0, 0, 0, 0, {}};
};

struct EMC_COOLANT_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_COOLANT_STAT, RCS_STAT_MSG)
    int32_t mist = 0;
    int32_t flood = 0;
};

struct EMC_AUX_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_AUX_STAT, RCS_STAT_MSG)
    int32_t estop = 1;
};

struct EMC_IO_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_IO_STAT, RCS_STAT_MSG)
    int32_t debug = 0;
    int32_t reason = 0;
    int32_t fault = 0;
    EMC_TOOL_STAT tool;
    EMC_COOLANT_STAT coolant;
    EMC_AUX_STAT aux;
};

// The whole status. echo_serial_number, status and command_type (RCS_STAT_MSG) are the
// ones UIs wait on; task copies them into task as well.
struct EMC_STAT : RCS_STAT_MSG {
    NML_MESSAGE(EMC_STAT, RCS_STAT_MSG)
    EMC_TASK_STAT task;
    EMC_MOTION_STAT motion;
    EMC_IO_STAT io;
    int32_t debug = 0;
};

#endif
