// py_host.hh: what the interpreter asks of its embedded Python (the rs274ngc_python.so plugin).
#ifndef OPENEMC_RS274NGC_PY_HOST_HH
#define OPENEMC_RS274NGC_PY_HOST_HH

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "remap_def.hh"

class Interp;

// The [PYTHON] section of the INI file (ini.md, LinuxCNC remap documentation).
struct PythonConfig {
    std::string toplevel;                  // TOPLEVEL script, "" = none
    std::vector<std::string> path_prepend; // PATH_PREPEND, in INI order
    std::vector<std::string> path_append;  // PATH_APPEND, in INI order
    int log_level = 0;                     // LOG_LEVEL
    bool reload_on_change = false;         // RELOAD_ON_CHANGE
    std::string ini_file;                  // the INI file (relative paths are taken from its directory)
};

// The result of one call into Python.
struct PyOutcome {
    enum Kind { OK, VALUE, SUSPEND, ERROR };
    Kind kind = OK;
    double value = 0;          // VALUE: the number a function returned
    std::string error;         // ERROR: the message for the operator
    PyGenerator generator;     // SUSPEND: the generator to resume after the queue buster
};

// Python modules the interpreter looks functions up in.
enum PyModuleKind { PY_OWORD, PY_REMAP, PY_NAMEDPARAMS };

// The embedded Python as the interpreter sees it; the plugin implements it.
class PyHost {
public:
    virtual ~PyHost() = default;
    // run TOPLEVEL (once); false with err set when it fails
    virtual bool start(std::string &err) = 0;
    // TOPLEVEL's __init__(self) after the interpreter is initialised
    virtual PyOutcome call_init() = 0;
    // TOPLEVEL's __delete__(self) at interpreter exit
    virtual PyOutcome call_delete() = 0;
    // true when module.name exists and is callable
    virtual bool callable(PyModuleKind module, const std::string &name) = 0;
    // oword.name(self, *args): VALUE, OK (returned None) or ERROR
    virtual PyOutcome call_oword(const std::string &name, const std::vector<double> &args) = 0;
    // remap.name(self, **words): OK, SUSPEND (yielded INTERP_EXECUTE_FINISH) or ERROR
    virtual PyOutcome call_remap(const std::string &name, const std::map<std::string, double> &words) = 0;
    // continue a suspended generator
    virtual PyOutcome resume(const PyGenerator &gen) = 0;
    // namedparams.name(self) for #<name>: VALUE or ERROR
    virtual PyOutcome named_param(const std::string &name) = 0;
    // callables with a leading underscore in module namedparams
    virtual std::vector<std::string> named_param_names() = 0;
    // a ;py, statement (run in TOPLEVEL's namespace)
    virtual PyOutcome run(const std::string &statement) = 0;
    // ;pyreload: run TOPLEVEL again
    virtual PyOutcome reload() = 0;
};

// Interface version of the plugin's exported table; a mismatch is refused at load.
constexpr int PY_PLUGIN_VERSION = 1;

// The table the plugin exports as "rs274ngc_python_plugin".
struct PyPluginOps {
    int version;
    // create the host for this interpreter; nullptr with err set on failure
    PyHost *(*create)(Interp &interp, const PythonConfig &config, std::string &err);
};

// Load the plugin (and libpython when the process has none) and create a host.
std::unique_ptr<PyHost> load_python_host(Interp &interp, const PythonConfig &config, std::string &err);

#endif
