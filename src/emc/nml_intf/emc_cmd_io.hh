// emc_cmd_io.hh: tool, aux, spindle and coolant commands (nml.md sec. 3).
#ifndef EMC_CMD_IO_HH
#define EMC_CMD_IO_HH

#include "emcpos.h"
#include "nml_base.hh"

// ---- tool

struct EMC_TOOL_CMD_MSG : RCS_CMD_MSG {
protected:
    EMC_TOOL_CMD_MSG(NMLTYPE t, uint32_t s) : RCS_CMD_MSG(t, s) {}
};

struct EMC_TOOL_HALT : EMC_TOOL_CMD_MSG {
    NML_MESSAGE(EMC_TOOL_HALT, EMC_TOOL_CMD_MSG)
};
struct EMC_TOOL_ABORT : EMC_TOOL_CMD_MSG {
    NML_MESSAGE(EMC_TOOL_ABORT, EMC_TOOL_CMD_MSG)
    int32_t reason = 0;
};
// T word: prepare tool (pocket = tool-table index found by the interpreter).
struct EMC_TOOL_PREPARE : EMC_TOOL_CMD_MSG {
    NML_MESSAGE(EMC_TOOL_PREPARE, EMC_TOOL_CMD_MSG)
    int32_t pocket = 0;
    int32_t tool = 0;
};
// M6
struct EMC_TOOL_LOAD : EMC_TOOL_CMD_MSG {
    NML_MESSAGE(EMC_TOOL_LOAD, EMC_TOOL_CMD_MSG)
};
struct EMC_TOOL_UNLOAD : EMC_TOOL_CMD_MSG {
    NML_MESSAGE(EMC_TOOL_UNLOAD, EMC_TOOL_CMD_MSG)
};
// "" = the INI's [EMCIO]TOOL_TABLE.
struct EMC_TOOL_LOAD_TOOL_TABLE : EMC_TOOL_CMD_MSG {
    NML_MESSAGE(EMC_TOOL_LOAD_TOOL_TABLE, EMC_TOOL_CMD_MSG)
    char file[LINELEN] = {};
};
// G10 L1/L10/L11: pocket is the tool-table index to overwrite.
struct EMC_TOOL_SET_OFFSET : EMC_TOOL_CMD_MSG {
    NML_MESSAGE(EMC_TOOL_SET_OFFSET, EMC_TOOL_CMD_MSG)
    int32_t pocket = 0;
    int32_t toolno = 0;
    EmcPose offset = {};
    double diameter = 0;
    double frontangle = 0;
    double backangle = 0;
    int32_t orientation = 0;
};
// M61
struct EMC_TOOL_SET_NUMBER : EMC_TOOL_CMD_MSG {
    NML_MESSAGE(EMC_TOOL_SET_NUMBER, EMC_TOOL_CMD_MSG)
    int32_t tool = 0;
};

// ---- aux (M66)

struct EMC_AUX_INPUT_WAIT : RCS_CMD_MSG {
    NML_MESSAGE(EMC_AUX_INPUT_WAIT, RCS_CMD_MSG)
    int32_t index = 0;
    int32_t input_type = 0;  // emc_aux_input_type
    int32_t wait_type = 0;   // emc_aux_wait_type
    double timeout = 0;      // seconds
};

// ---- spindle: every command names a spindle (0-based)

struct EMC_SPINDLE_CMD_MSG : RCS_CMD_MSG {
    int32_t spindle = 0;

protected:
    EMC_SPINDLE_CMD_MSG(NMLTYPE t, uint32_t s) : RCS_CMD_MSG(t, s) {}
};

// speed: signed rpm (or the CSS maximum); factor: CSS numerator, 0 = rpm mode.
struct EMC_SPINDLE_ON : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_ON, EMC_SPINDLE_CMD_MSG)
    int32_t wait_for_spindle_at_speed = 0;
    double speed = 0;
    double factor = 0;
    double xoffset = 0;
};
struct EMC_SPINDLE_OFF : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_OFF, EMC_SPINDLE_CMD_MSG)
    int32_t wait_for_spindle_at_speed = 0;
};
struct EMC_SPINDLE_INCREASE : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_INCREASE, EMC_SPINDLE_CMD_MSG)
    double speed = 0;
};
struct EMC_SPINDLE_DECREASE : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_DECREASE, EMC_SPINDLE_CMD_MSG)
    double speed = 0;
};
struct EMC_SPINDLE_CONSTANT : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_CONSTANT, EMC_SPINDLE_CMD_MSG)
    double speed = 0;
};
struct EMC_SPINDLE_BRAKE_RELEASE : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_BRAKE_RELEASE, EMC_SPINDLE_CMD_MSG)
};
struct EMC_SPINDLE_BRAKE_ENGAGE : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_BRAKE_ENGAGE, EMC_SPINDLE_CMD_MSG)
};
struct EMC_SPINDLE_SPEED : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_SPEED, EMC_SPINDLE_CMD_MSG)
    double speed = 0;
    double factor = 0;
    double xoffset = 0;
};
// M19
struct EMC_SPINDLE_ORIENT : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_ORIENT, EMC_SPINDLE_CMD_MSG)
    int32_t mode = 0;
    double orientation = 0;  // degrees
};
struct EMC_SPINDLE_WAIT_ORIENT_COMPLETE : EMC_SPINDLE_CMD_MSG {
    NML_MESSAGE(EMC_SPINDLE_WAIT_ORIENT_COMPLETE, EMC_SPINDLE_CMD_MSG)
    double timeout = 0;  // seconds
};

// ---- coolant

struct EMC_COOLANT_MIST_ON : RCS_CMD_MSG {
    NML_MESSAGE(EMC_COOLANT_MIST_ON, RCS_CMD_MSG)
};
struct EMC_COOLANT_MIST_OFF : RCS_CMD_MSG {
    NML_MESSAGE(EMC_COOLANT_MIST_OFF, RCS_CMD_MSG)
};
struct EMC_COOLANT_FLOOD_ON : RCS_CMD_MSG {
    NML_MESSAGE(EMC_COOLANT_FLOOD_ON, RCS_CMD_MSG)
};
struct EMC_COOLANT_FLOOD_OFF : RCS_CMD_MSG {
    NML_MESSAGE(EMC_COOLANT_FLOOD_OFF, RCS_CMD_MSG)
};

#endif
