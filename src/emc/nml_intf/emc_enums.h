/* emc_enums.h: the enumerations of the task/status protocol with LinuxCNC's values (nml.md sec. 4, python.md). */
#ifndef EMC_ENUMS_H
#define EMC_ENUMS_H

/* Array sizes of the status structure. */
#define EMCMOT_MAX_JOINTS 16
#define EMCMOT_MAX_AXIS 9
#define EMCMOT_MAX_SPINDLES 8
#define EMCMOT_MAX_DIO 64
#define EMCMOT_MAX_AIO 64
#define EMCMOT_MAX_MISC_ERROR 64
#define CANON_POCKETS_MAX 1001
/* Length of the text fields (file names, MDI text, operator messages), NUL included. */
#define LINELEN 255
/* Bytes of EMC_TASK_PLAN_OPEN.remote_buffer. */
#define EMC_TASK_PLAN_OPEN_REMOTE_BUFFER 4096

/* RCS status of a status message (EMC_STAT.status, Python stat.state). */
enum rcs_status {
    UNINITIALIZED_STATUS = -1,
    RCS_DONE = 1,
    RCS_EXEC = 2,
    RCS_ERROR = 3,
};

/* EMC_TASK_SET_MODE.mode, EMC_TASK_STAT.mode. */
enum emc_task_mode {
    EMC_TASK_MODE_MANUAL = 1,
    EMC_TASK_MODE_AUTO = 2,
    EMC_TASK_MODE_MDI = 3,
};

/* EMC_TASK_SET_STATE.state, EMC_TASK_STAT.state. */
enum emc_task_state {
    EMC_TASK_STATE_ESTOP = 1,
    EMC_TASK_STATE_ESTOP_RESET = 2,
    EMC_TASK_STATE_OFF = 3,
    EMC_TASK_STATE_ON = 4,
};

/* EMC_TASK_STAT.interpState. */
enum emc_task_interp_state {
    EMC_TASK_INTERP_IDLE = 1,
    EMC_TASK_INTERP_READING = 2,
    EMC_TASK_INTERP_PAUSED = 3,
    EMC_TASK_INTERP_WAITING = 4,
};

/* EMC_TASK_STAT.execState (there is no 6). */
enum emc_task_exec_state {
    EMC_TASK_EXEC_ERROR = 1,
    EMC_TASK_EXEC_DONE = 2,
    EMC_TASK_EXEC_WAITING_FOR_MOTION = 3,
    EMC_TASK_EXEC_WAITING_FOR_MOTION_QUEUE = 4,
    EMC_TASK_EXEC_WAITING_FOR_IO = 5,
    EMC_TASK_EXEC_WAITING_FOR_MOTION_AND_IO = 7,
    EMC_TASK_EXEC_WAITING_FOR_DELAY = 8,
    EMC_TASK_EXEC_WAITING_FOR_SYSTEM_CMD = 9,
    EMC_TASK_EXEC_WAITING_FOR_SPINDLE_ORIENTED = 10,
};

/* EMC_TRAJ_SET_MODE.mode, EMC_TRAJ_STAT.mode. */
enum emc_traj_mode {
    EMC_TRAJ_MODE_FREE = 1,
    EMC_TRAJ_MODE_COORD = 2,
    EMC_TRAJ_MODE_TELEOP = 3,
};

/* EMC_TRAJ_SET_TERM_COND.cond. */
enum emc_traj_term_cond {
    EMC_TRAJ_TERM_COND_STOP = 0,
    EMC_TRAJ_TERM_COND_EXACT = 1,
    EMC_TRAJ_TERM_COND_BLEND = 2,
};

/* EMC_TRAJ_STAT.motion_type (0 = no motion). */
enum emc_motion_type {
    EMC_MOTION_TYPE_NONE = 0,
    EMC_MOTION_TYPE_TRAVERSE = 1,
    EMC_MOTION_TYPE_FEED = 2,
    EMC_MOTION_TYPE_ARC = 3,
    EMC_MOTION_TYPE_TOOLCHANGE = 4,
    EMC_MOTION_TYPE_PROBING = 5,
    EMC_MOTION_TYPE_INDEXROTARY = 6,
};

/* EMC_TRAJ_STAT.kinematics_type (same values as kins_ops.h KINEMATICS_*). */
enum emc_kinematics_type {
    EMC_KINEMATICS_IDENTITY = 1,
    EMC_KINEMATICS_FORWARD_ONLY = 2,
    EMC_KINEMATICS_INVERSE_ONLY = 3,
    EMC_KINEMATICS_BOTH = 4,
};

/* EMC_JOINT_STAT.jointType. */
enum emc_joint_type {
    EMC_LINEAR = 1,
    EMC_ANGULAR = 2,
};

/* EMC_AUX_INPUT_WAIT.input_type and wait_type (M66). */
enum emc_aux_input_type {
    EMC_AUX_INPUT_DIGITAL = 0,
    EMC_AUX_INPUT_ANALOG = 1,
};
enum emc_aux_wait_type {
    EMC_AUX_WAIT_IMMEDIATE = 0,
    EMC_AUX_WAIT_RISE = 1,
    EMC_AUX_WAIT_FALL = 2,
    EMC_AUX_WAIT_HIGH = 3,
    EMC_AUX_WAIT_LOW = 4,
};

/* EMC_JOINT_HOME.joint / EMC_JOINT_UNHOME.joint special values. */
#define EMC_JOINT_ALL (-1)
#define EMC_JOINT_VOLATILE_ONLY (-2)

/* EMC_JOG_*.jjogmode. */
#define EMC_JOG_AXIS 0
#define EMC_JOG_JOINT 1

/* EMC_STAT.debug / EMC_SET_DEBUG.debug bits. */
#define EMC_DEBUG_CONFIG 0x00000002
#define EMC_DEBUG_VERSIONS 0x00000008
#define EMC_DEBUG_TASK_ISSUE 0x00000010
#define EMC_DEBUG_NML 0x00000040
#define EMC_DEBUG_MOTION_TIME 0x00000080
#define EMC_DEBUG_INTERP 0x00000100
#define EMC_DEBUG_RCS 0x00000200
#define EMC_DEBUG_INTERP_LIST 0x00000800
#define EMC_DEBUG_OWORD 0x00002000
#define EMC_DEBUG_REMAP 0x00004000
#define EMC_DEBUG_PYTHON 0x00008000
#define EMC_DEBUG_STATE_TAGS 0x00080000

#endif
