// lcnc_command.hh: the linuxcnc.command object shared by its core (send/wait) and its method handlers.
#ifndef LCNC_COMMAND_HH
#define LCNC_COMMAND_HH

#include <vector>

#include "lcnc_py.hh"

// A linuxcnc.command object.
struct PyCommand {
    PyObject_HEAD
    LcncLink *cmd;      // emcCommand (write)
    LcncLink *stat;     // emcStatus (to watch the echo)
    EMC_STAT *scratch;  // status copies made while waiting
    int32_t serial;     // serial of the last command sent
};

// Write msg and wait (GIL released) until task has read it; None, or NULL with an
// exception. Not running: nothing is sent and None is returned.
PyObject *lcnc_command_send(PyObject *self, const NMLmsg &msg);
// The command methods, NULL-terminated.
std::vector<PyMethodDef> lcnc_command_methods();

#endif
