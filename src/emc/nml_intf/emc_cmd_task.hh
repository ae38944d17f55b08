// emc_cmd_task.hh: operator messages, debug, system commands and task/program commands (nml.md sec. 3).
#ifndef EMC_CMD_TASK_HH
#define EMC_CMD_TASK_HH

#include "nml_base.hh"

// Operator messages: UIs send them on emcCommand, task copies them to emcError.
struct EMC_OPERATOR_ERROR : RCS_CMD_MSG {
    NML_MESSAGE(EMC_OPERATOR_ERROR, RCS_CMD_MSG)
    char error[LINELEN] = {};
};
struct EMC_OPERATOR_TEXT : RCS_CMD_MSG {
    NML_MESSAGE(EMC_OPERATOR_TEXT, RCS_CMD_MSG)
    char text[LINELEN] = {};
};
struct EMC_OPERATOR_DISPLAY : RCS_CMD_MSG {
    NML_MESSAGE(EMC_OPERATOR_DISPLAY, RCS_CMD_MSG)
    char display[LINELEN] = {};
};

struct EMC_NULL : RCS_CMD_MSG {
    NML_MESSAGE(EMC_NULL, RCS_CMD_MSG)
};
struct EMC_SET_DEBUG : RCS_CMD_MSG {
    NML_MESSAGE(EMC_SET_DEBUG, RCS_CMD_MSG)
    int32_t debug = 0;  // EMC_DEBUG_* bits
};
// Runs a shell command (M100-M199).
struct EMC_SYSTEM_CMD : RCS_CMD_MSG {
    NML_MESSAGE(EMC_SYSTEM_CMD, RCS_CMD_MSG)
    char string[LINELEN] = {};
};

struct EMC_TASK_CMD_MSG : RCS_CMD_MSG {
protected:
    EMC_TASK_CMD_MSG(NMLTYPE t, uint32_t s) : RCS_CMD_MSG(t, s) {}
};

struct EMC_TASK_ABORT : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_ABORT, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_SET_MODE : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_SET_MODE, EMC_TASK_CMD_MSG)
    int32_t mode = 0;  // emc_task_mode
};
struct EMC_TASK_SET_STATE : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_SET_STATE, EMC_TASK_CMD_MSG)
    int32_t state = 0;  // emc_task_state
};
// Open a program; remote clients stream the file through remote_buffer in chunks.
struct EMC_TASK_PLAN_OPEN : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_OPEN, EMC_TASK_CMD_MSG)
    char file[LINELEN] = {};
    int32_t remote_filesize = 0;
    int32_t remote_buffersize = 0;
    char remote_buffer[EMC_TASK_PLAN_OPEN_REMOTE_BUFFER] = {};
};
// line 0: from the start; n > 0: read lines < n without executing, start at n; < 0: verify only.
struct EMC_TASK_PLAN_RUN : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_RUN, EMC_TASK_CMD_MSG)
    int32_t line = 0;
};
// MDI text.
struct EMC_TASK_PLAN_EXECUTE : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_EXECUTE, EMC_TASK_CMD_MSG)
    char command[LINELEN] = {};
};
struct EMC_TASK_PLAN_PAUSE : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_PAUSE, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_STEP : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_STEP, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_RESUME : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_RESUME, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_END : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_END, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_CLOSE : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_CLOSE, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_INIT : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_INIT, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_SYNCH : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_SYNCH, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_SET_OPTIONAL_STOP : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_SET_OPTIONAL_STOP, EMC_TASK_CMD_MSG)
    uint8_t state = 0;  // 0/1
};
struct EMC_TASK_PLAN_SET_BLOCK_DELETE : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_SET_BLOCK_DELETE, EMC_TASK_CMD_MSG)
    uint8_t state = 0;  // 0/1
};
// M1 (queued in the interp list).
struct EMC_TASK_PLAN_OPTIONAL_STOP : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_OPTIONAL_STOP, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_REVERSE : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_REVERSE, EMC_TASK_CMD_MSG)
};
struct EMC_TASK_PLAN_FORWARD : EMC_TASK_CMD_MSG {
    NML_MESSAGE(EMC_TASK_PLAN_FORWARD, EMC_TASK_CMD_MSG)
};

#endif
