// emc_cmd_motion.hh: joint, jog, trajectory and motion I/O commands (nml.md sec. 3).
#ifndef EMC_CMD_MOTION_HH
#define EMC_CMD_MOTION_HH

#include "emcpos.h"
#include "nml_base.hh"
#include "state_tag.h"

// ---- joints: every command names a joint (0-based; -1 = all where noted)

struct EMC_JOINT_CMD_MSG : RCS_CMD_MSG {
    int32_t joint = 0;

protected:
    EMC_JOINT_CMD_MSG(NMLTYPE t, uint32_t s) : RCS_CMD_MSG(t, s) {}
};

struct EMC_JOINT_SET_MIN_POSITION_LIMIT : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_SET_MIN_POSITION_LIMIT, EMC_JOINT_CMD_MSG)
    double limit = 0;
};
struct EMC_JOINT_SET_MAX_POSITION_LIMIT : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_SET_MAX_POSITION_LIMIT, EMC_JOINT_CMD_MSG)
    double limit = 0;
};
struct EMC_JOINT_SET_FERROR : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_SET_FERROR, EMC_JOINT_CMD_MSG)
    double ferror = 0;
};
struct EMC_JOINT_SET_MIN_FERROR : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_SET_MIN_FERROR, EMC_JOINT_CMD_MSG)
    double ferror = 0;
};
struct EMC_JOINT_SET_HOMING_PARAMS : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_SET_HOMING_PARAMS, EMC_JOINT_CMD_MSG)
    double home = 0;
    double offset = 0;
    double home_final_vel = 0;
    double search_vel = 0;
    double latch_vel = 0;
    int32_t use_index = 0;
    int32_t encoder_does_not_reset = 0;
    int32_t ignore_limits = 0;
    int32_t is_shared = 0;
    int32_t home_sequence = 0;
    int32_t volatile_home = 0;
    int32_t locking_indexer = 0;
    int32_t absolute_encoder = 0;
};
struct EMC_JOINT_HALT : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_HALT, EMC_JOINT_CMD_MSG)
};
// joint -1 = home all in HOME_SEQUENCE order.
struct EMC_JOINT_HOME : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_HOME, EMC_JOINT_CMD_MSG)
};
// joint -1 = all, -2 = only VOLATILE_HOME joints.
struct EMC_JOINT_UNHOME : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_UNHOME, EMC_JOINT_CMD_MSG)
};
struct EMC_JOINT_OVERRIDE_LIMITS : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_OVERRIDE_LIMITS, EMC_JOINT_CMD_MSG)
};
struct EMC_JOINT_LOAD_COMP : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_LOAD_COMP, EMC_JOINT_CMD_MSG)
    char file[LINELEN] = {};
    int32_t type = 0;  // comp file type 0/1
};
struct EMC_JOINT_SET_BACKLASH : EMC_JOINT_CMD_MSG {
    NML_MESSAGE(EMC_JOINT_SET_BACKLASH, EMC_JOINT_CMD_MSG)
    double backlash = 0;
};

// ---- jogs: joint_or_axis is a joint number (jjogmode 1) or axis 0..8 = XYZABCUVW (0)

struct EMC_JOG_CMD_MSG : RCS_CMD_MSG {
    int32_t joint_or_axis = 0;
    int32_t jjogmode = 0;  // EMC_JOG_JOINT / EMC_JOG_AXIS

protected:
    EMC_JOG_CMD_MSG(NMLTYPE t, uint32_t s) : RCS_CMD_MSG(t, s) {}
};

struct EMC_JOG_CONT : EMC_JOG_CMD_MSG {
    NML_MESSAGE(EMC_JOG_CONT, EMC_JOG_CMD_MSG)
    double vel = 0;
};
struct EMC_JOG_INCR : EMC_JOG_CMD_MSG {
    NML_MESSAGE(EMC_JOG_INCR, EMC_JOG_CMD_MSG)
    double incr = 0;
    double vel = 0;
};
struct EMC_JOG_ABS : EMC_JOG_CMD_MSG {
    NML_MESSAGE(EMC_JOG_ABS, EMC_JOG_CMD_MSG)
    double pos = 0;
    double vel = 0;
};
struct EMC_JOG_STOP : EMC_JOG_CMD_MSG {
    NML_MESSAGE(EMC_JOG_STOP, EMC_JOG_CMD_MSG)
};

// ---- trajectory

struct EMC_TRAJ_CMD_MSG : RCS_CMD_MSG {
protected:
    EMC_TRAJ_CMD_MSG(NMLTYPE t, uint32_t s) : RCS_CMD_MSG(t, s) {}
};

struct EMC_TRAJ_SET_MODE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_MODE, EMC_TRAJ_CMD_MSG)
    int32_t mode = 0;  // emc_traj_mode
};
struct EMC_TRAJ_SET_VELOCITY : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_VELOCITY, EMC_TRAJ_CMD_MSG)
    double velocity = 0;
    double ini_maxvel = 0;
};
struct EMC_TRAJ_SET_ACCELERATION : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_ACCELERATION, EMC_TRAJ_CMD_MSG)
    double acceleration = 0;
};
struct EMC_TRAJ_SET_MAX_VELOCITY : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_MAX_VELOCITY, EMC_TRAJ_CMD_MSG)
    double velocity = 0;
};
// Feed override (1.0 = 100 %).
struct EMC_TRAJ_SET_SCALE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_SCALE, EMC_TRAJ_CMD_MSG)
    double scale = 0;
};
struct EMC_TRAJ_SET_RAPID_SCALE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_RAPID_SCALE, EMC_TRAJ_CMD_MSG)
    double scale = 0;
};
struct EMC_TRAJ_ABORT : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_ABORT, EMC_TRAJ_CMD_MSG)
};
struct EMC_TRAJ_PAUSE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_PAUSE, EMC_TRAJ_CMD_MSG)
};
struct EMC_TRAJ_RESUME : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_RESUME, EMC_TRAJ_CMD_MSG)
};
struct EMC_TRAJ_DELAY : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_DELAY, EMC_TRAJ_CMD_MSG)
    double delay = 0;  // seconds
};
struct EMC_TRAJ_LINEAR_MOVE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_LINEAR_MOVE, EMC_TRAJ_CMD_MSG)
    EmcPose end = {};
    int32_t type = 0;       // emc_motion_type
    int32_t feed_mode = 0;
    double vel = 0;
    double ini_maxvel = 0;
    double acc = 0;
    int32_t indexer_jnum = -1;  // locking indexer joint, -1 none
    state_tag_t tag = {};
};
struct EMC_TRAJ_CIRCULAR_MOVE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_CIRCULAR_MOVE, EMC_TRAJ_CMD_MSG)
    EmcPose end = {};
    PmCartesian center = {};
    PmCartesian normal = {};
    int32_t turn = 0;
    int32_t type = 0;
    int32_t feed_mode = 0;
    double vel = 0;
    double ini_maxvel = 0;
    double acc = 0;
    state_tag_t tag = {};
};
struct EMC_TRAJ_SET_TERM_COND : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_TERM_COND, EMC_TRAJ_CMD_MSG)
    int32_t cond = 0;  // emc_traj_term_cond
    int32_t planner_type = 0;
    double tolerance = 0;
    double scurve_peak_scale = 0;
};
// Tool length offset.
struct EMC_TRAJ_SET_OFFSET : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_OFFSET, EMC_TRAJ_CMD_MSG)
    EmcPose offset = {};
};
struct EMC_TRAJ_SET_G5X : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_G5X, EMC_TRAJ_CMD_MSG)
    int32_t g5x_index = 0;  // 1..9 (G54 = 1)
    EmcPose origin = {};
};
struct EMC_TRAJ_SET_ROTATION : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_ROTATION, EMC_TRAJ_CMD_MSG)
    double rotation = 0;  // degrees
};
struct EMC_TRAJ_SET_G92 : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_G92, EMC_TRAJ_CMD_MSG)
    EmcPose origin = {};
};
struct EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG, EMC_TRAJ_CMD_MSG)
};
struct EMC_TRAJ_PROBE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_PROBE, EMC_TRAJ_CMD_MSG)
    EmcPose pos = {};
    int32_t type = 0;
    int32_t probe_type = 0;  // G38.n: 2..5 as 0..3 plus flags, as motion expects
    double vel = 0;
    double ini_maxvel = 0;
    double acc = 0;
    state_tag_t tag = {};
};
struct EMC_TRAJ_SET_TELEOP_ENABLE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_TELEOP_ENABLE, EMC_TRAJ_CMD_MSG)
    int32_t enable = 0;
};
struct EMC_TRAJ_SET_SPINDLESYNC : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_SPINDLESYNC, EMC_TRAJ_CMD_MSG)
    int32_t spindle = 0;
    int32_t velocity_mode = 0;
    double feed_per_revolution = 0;
};
struct EMC_TRAJ_SET_SPINDLE_SCALE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_SPINDLE_SCALE, EMC_TRAJ_CMD_MSG)
    int32_t spindle = 0;
    double scale = 0;
};
struct EMC_TRAJ_SET_FO_ENABLE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_FO_ENABLE, EMC_TRAJ_CMD_MSG)
    uint8_t mode = 0;
};
struct EMC_TRAJ_SET_SO_ENABLE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_SO_ENABLE, EMC_TRAJ_CMD_MSG)
    uint8_t mode = 0;
    int32_t spindle = 0;
};
struct EMC_TRAJ_SET_FH_ENABLE : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_SET_FH_ENABLE, EMC_TRAJ_CMD_MSG)
    uint8_t mode = 0;
};
struct EMC_TRAJ_RIGID_TAP : EMC_TRAJ_CMD_MSG {
    NML_MESSAGE(EMC_TRAJ_RIGID_TAP, EMC_TRAJ_CMD_MSG)
    EmcPose pos = {};
    double vel = 0;
    double ini_maxvel = 0;
    double acc = 0;
    double scale = 0;
    state_tag_t tag = {};
};

// ---- motion I/O (M62-M68)

struct EMC_MOTION_CMD_MSG : RCS_CMD_MSG {
protected:
    EMC_MOTION_CMD_MSG(NMLTYPE t, uint32_t s) : RCS_CMD_MSG(t, s) {}
};

struct EMC_MOTION_SET_AOUT : EMC_MOTION_CMD_MSG {
    NML_MESSAGE(EMC_MOTION_SET_AOUT, EMC_MOTION_CMD_MSG)
    uint8_t index = 0;
    uint8_t now = 0;  // 1 = immediate, 0 = with the next motion
    double start = 0;
    double end = 0;
};
struct EMC_MOTION_SET_DOUT : EMC_MOTION_CMD_MSG {
    NML_MESSAGE(EMC_MOTION_SET_DOUT, EMC_MOTION_CMD_MSG)
    uint8_t index = 0;
    uint8_t start = 0;
    uint8_t end = 0;
    uint8_t now = 0;
};
struct EMC_MOTION_ADAPTIVE : EMC_MOTION_CMD_MSG {
    NML_MESSAGE(EMC_MOTION_ADAPTIVE, EMC_MOTION_CMD_MSG)
    uint8_t status = 0;  // 0/1
};

#endif
