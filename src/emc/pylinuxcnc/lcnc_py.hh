// lcnc_py.hh: declarations shared by the source files of the Python `linuxcnc` module.
#ifndef LCNC_PY_HH
#define LCNC_PY_HH

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <memory>
#include <string>

#include "emc_nml.hh"

// Argument values of command methods (also module constants).
enum LcncArg : long {
    LCNC_SPINDLE_FORWARD = 1,
    LCNC_SPINDLE_REVERSE = -1,
    LCNC_SPINDLE_OFF = 0,
    LCNC_SPINDLE_INCREASE = 10,
    LCNC_SPINDLE_DECREASE = 11,
    LCNC_SPINDLE_CONSTANT = 12,
    LCNC_COOLANT_ON = 1,   // MIST_ON, FLOOD_ON
    LCNC_COOLANT_OFF = 0,  // MIST_OFF, FLOOD_OFF
    LCNC_BRAKE_ENGAGE = 1,
    LCNC_BRAKE_RELEASE = 0,
    LCNC_JOG_STOP = 0,
    LCNC_JOG_CONTINUOUS = 1,
    LCNC_JOG_INCREMENT = 2,
    LCNC_AUTO_RUN = 0,
    LCNC_AUTO_PAUSE = 1,
    LCNC_AUTO_RESUME = 2,
    LCNC_AUTO_STEP = 3,
    LCNC_AUTO_REVERSE = 4,
    LCNC_AUTO_FORWARD = 5,
};

// The module object and linuxcnc.error (a RuntimeError subclass shared with linuxcnc.ini).
extern PyObject *lcnc_module;
extern PyObject *lcnc_error;

// A channel object's lazily attached connection to one buffer, as process xemc.
// Objects can be made before LinuxCNC runs; they attach at first use and reattach when
// linuxcncsvr was restarted.
class LcncLink {
public:
    // Remember the buffer and the module's current nmlfile.
    explicit LcncLink(const char *buffer);
    // Attached to a live buffer (attaching now if needed); false with error() set.
    bool ready();
    // The channel (only after ready() returned true).
    EmcChannel &channel() { return *channel_; }
    nml_channel_t *raw() { return channel_->raw(); }
    const std::string &error() const { return error_; }
    const std::string &nml_file() const { return nml_file_; }

private:
    std::string buffer_;
    std::string nml_file_;
    std::unique_ptr<EmcChannel> channel_;
    std::string error_;
};

// Copy the current EMC_STAT of a status link into out: 1 copied, 0 nothing written yet,
// -1 with a Python exception set when the buffer holds something else.
int lcnc_peek_status(LcncLink &link, EMC_STAT &out);

// linuxcnc.stat objects.
struct PyStat {
    PyObject_HEAD
    EMC_STAT status;  // copy of the last poll (all zero before the first one)
    LcncLink *link;
    int polled;
};

// Type objects (created at module init).
extern PyTypeObject *lcnc_stat_type;
extern PyTypeObject *lcnc_tool_type;

// Module set-up of each part; 0 or -1 with an exception set.
int lcnc_add_constants(PyObject *module);
int lcnc_add_stat(PyObject *module);
int lcnc_add_command(PyObject *module);
int lcnc_add_error_channel(PyObject *module);
int lcnc_add_logger(PyObject *module);
int lcnc_add_preview(PyObject *module);
int lcnc_add_tool(PyObject *module);

// Getset table entries of the computed stat attributes (tuples and dicts), NULL-terminated.
extern PyGetSetDef lcnc_stat_tuple_getsets[];
// stat.tool_table getter and stat.toolinfo method.
PyObject *lcnc_stat_tool_table(PyObject *self, void *);
PyObject *lcnc_stat_toolinfo(PyObject *self, PyObject *args);
// Attach the tool data (first poll of any stat object).
void lcnc_tool_attach();

// Python str of a fixed text field (bounded, undecodable bytes kept as surrogates).
PyObject *lcnc_text(const char *field, size_t size);
// Tuple of the nine components of a pose.
PyObject *lcnc_pose_tuple(const EmcPose &p);

#endif
