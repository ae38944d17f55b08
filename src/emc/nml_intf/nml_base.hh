// nml_base.hh: the base classes every NML message derives from (NMLmsg, RCS_CMD_MSG, RCS_STAT_MSG) and libnml's own messages.
#ifndef NML_BASE_HH
#define NML_BASE_HH

#include <cstdint>

#include "emc_enums.h"
#include "emc_msg_list.h"
#include "nml.h"

typedef int32_t NMLTYPE;

// Header of every message. Messages are plain data (trivially copyable): a buffer holds
// their bytes, and the codec (emc_codec.hh) checks type, size and text fields before a
// reader may look at them as a class.
struct NMLmsg {
    NMLTYPE type;
    uint32_t size;          // sizeof the concrete class
    int32_t serial_number;  // stamped by a `serial` buffer (emcCommand) on write
    uint32_t reserved_;

protected:
    NMLmsg(NMLTYPE t, uint32_t s) : type(t), size(s), serial_number(0), reserved_(0) {}
};
static_assert(sizeof(NMLmsg) == sizeof(nml_msg_hdr_t), "NMLmsg must match nml_msg_hdr_t");

// A command (UI -> task).
struct RCS_CMD_MSG : NMLmsg {
protected:
    RCS_CMD_MSG(NMLTYPE t, uint32_t s) : NMLmsg(t, s) {}
};

// A status (task -> UI): which command task last read and how it is doing.
struct RCS_STAT_MSG : NMLmsg {
    NMLTYPE command_type = 0;        // type of the last command read
    int32_t echo_serial_number = 0;  // its serial_number
    int32_t status = 0;              // rcs_status: RCS_DONE / RCS_EXEC / RCS_ERROR
    int32_t reserved_stat_ = 0;

protected:
    RCS_STAT_MSG(NMLTYPE t, uint32_t s) : NMLmsg(t, s) {}
};

// Declares the type constant and the default constructor of a concrete message class.
#define NML_MESSAGE(name, base)                             \
    static constexpr NMLTYPE TYPE = name##_TYPE;           \
    name() : base(name##_TYPE, sizeof(name)) {}

// Declares the constructor of an abstract group base (e.g. EMC_JOINT_CMD_MSG).
#define NML_GROUP(name, base) \
protected:                    \
    name(NMLTYPE t, uint32_t s) : base(t, s) {} \
public:

// libnml's own text messages (types 1-3).
struct NML_ERROR : NMLmsg {
    NML_MESSAGE(NML_ERROR, NMLmsg)
    char error[LINELEN] = {};
};
struct NML_TEXT : NMLmsg {
    NML_MESSAGE(NML_TEXT, NMLmsg)
    char text[LINELEN] = {};
};
struct NML_DISPLAY : NMLmsg {
    NML_MESSAGE(NML_DISPLAY, NMLmsg)
    char display[LINELEN] = {};
};

#endif
