// py_start.hh: the process-wide state of the embedded Python (started once, shared by every interpreter).
#ifndef OPENEMC_RS274NGC_PY_START_HH
#define OPENEMC_RS274NGC_PY_START_HH

#include <ctime>
#include <string>

#include "../py_host.hh"
#include "py_util.hh"

// What the process's embedded Python holds.
struct PyProcess {
    bool embedded = false;     // this plugin started the runtime (rs274, task), not a Python program
    bool ready = false;        // modules registered
    PyRef interpreter;         // module `interpreter`
    PyRef self;                // interpreter.this, the `self` of every call
    PyRef toplevel;            // the module TOPLEVEL ran in (its dict holds oword, remap, namedparams)
    std::string toplevel_path;
    time_t toplevel_mtime = 0;
};

// The process-wide Python state.
PyProcess &py_process();
// Start the runtime (when the process has none) and the modules; false with err set.
bool py_process_start(std::string &err);
// Put the [PYTHON] PATH_PREPEND / PATH_APPEND directories on sys.path; false with err set.
bool py_process_paths(const PythonConfig &cfg, std::string &err);
// Run the TOPLEVEL script (path "" = none: an empty namespace for ;py, statements); false with err set.
bool py_process_toplevel(const std::string &path, std::string &err);
// True when TOPLEVEL changed on disk since it ran (RELOAD_ON_CHANGE).
bool py_process_toplevel_changed();

#endif
