// py_plugin.hh: shared declarations of the embedded-Python plugin (rs274ngc_python.so).
#ifndef OPENEMC_RS274NGC_PY_PLUGIN_HH
#define OPENEMC_RS274NGC_PY_PLUGIN_HH

#include "../interp_base.hh"
#include "py_util.hh"

class Interp;

// LinuxCNC's interpreter return codes, as Python code sees them (interpreter.INTERP_*).
enum PyInterpCode { PY_INTERP_OK = 0, PY_INTERP_EXIT = 1, PY_INTERP_EXECUTE_FINISH = 2,
                    PY_INTERP_ENDFILE = 3, PY_INTERP_FILE_NOT_OPEN = 4, PY_INTERP_ERROR = 5,
                    PY_INTERP_MIN_ERROR = 3 };

// What the modules need to know about the interpreter currently calling Python.
struct PyEnv {
    Interp *interp = nullptr;  // the interpreter that called into Python (one at a time)
    int debugmask = 0;         // [EMC]DEBUG (plus LinuxCNC's always-on bit)
    int logging_level = 0;     // [RS274NGC]LOG_LEVEL
};

// The process-wide environment the modules read.
PyEnv &py_env();

// The private module `_rs274ngc` (interpreter state for interpreter.py), new reference.
PyObject *make_state_module();
// The `emccanon` module (canon calls), new reference.
PyObject *make_canon_module();
// Map an interpreter status to LinuxCNC's code (only INTERP_ERROR differs).
inline int py_interp_code(int status)
{
    return status == INTERP_ERROR ? PY_INTERP_ERROR : status;
}

#endif
