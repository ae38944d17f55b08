// py_plugin.cc: the embedded-Python plugin (rs274ngc_python.so): the PyHost the interpreter calls for
// remap prologs/bodies/epilogs, Python O-word subroutines, namedparams and ;py, statements.
#include <cctype>
#include <cstdio>
#include <map>

#include "inifile.hh"
#include "interp_access.hh"
#include "py_plugin.hh"
#include "py_start.hh"

namespace {

// LinuxCNC's always-on debug bit, part of every interpreter's debugmask.
constexpr int EMC_DEBUG_UNCONDITIONAL = 0x40000000;

const char *const MODULE_NAMES[] = {"oword", "remap", "namedparams"};

// Makes `interp` the one Python talks to for the length of a call; keeps stdout and stderr in order.
class Enter {
public:
    explicit Enter(Interp &i) : saved_(py_env().interp)
    {
        py_env().interp = &i;
        flush_c_output();
    }
    ~Enter()
    {
        flush_py_output();
        py_env().interp = saved_;
    }
    Enter(const Enter &) = delete;
    Enter &operator=(const Enter &) = delete;

private:
    Interp *saved_;
};

// an ERROR outcome
PyOutcome error(const std::string &text)
{
    PyOutcome o;
    o.kind = PyOutcome::ERROR;
    o.error = text;
    return o;
}

// an ERROR outcome for the pending Python exception, prefixed with where it happened
PyOutcome python_error(const std::string &where)
{
    return error(where + ":\n" + py_error_text());
}

// a generator the interpreter keeps while it waits; released under the GIL
PyGenerator keep_generator(PyObject *gen)
{
    Py_INCREF(gen);
    return PyGenerator(gen, [](void *g) {
        GilLock gil;
        Py_DECREF(static_cast<PyObject *>(g));
    });
}

// the type name of a Python object, for messages
std::string type_name(PyObject *o)
{
    return Py_TYPE(o)->tp_name;
}

class PythonHost : public PyHost {
public:
    PythonHost(Interp &interp, const PythonConfig &cfg) : interp_(interp), cfg_(cfg) {}

    bool start(std::string &err) override;
    PyOutcome call_init() override { return call_toplevel("__init__"); }
    PyOutcome call_delete() override { return call_toplevel("__delete__"); }
    bool callable(PyModuleKind module, const std::string &name) override;
    PyOutcome call_oword(const std::string &name, const std::vector<double> &args) override;
    PyOutcome call_remap(const std::string &name, const std::map<std::string, double> &words) override;
    PyOutcome resume(const PyGenerator &gen) override;
    PyOutcome named_param(const std::string &name) override;
    std::vector<std::string> named_param_names() override;
    PyOutcome run(const std::string &statement) override;
    PyOutcome reload() override;

private:
    PyObject *module(PyModuleKind m);
    PyObject *function(PyModuleKind m, const std::string &name);
    PyOutcome call_toplevel(const char *name);
    PyOutcome step(PyObject *gen, const std::string &where);
    PyOutcome remap_result(PyObject *r, const std::string &where);
    void reload_if_changed();
    void log(int level, const std::string &text) const;

    Interp &interp_;
    PythonConfig cfg_;
    std::map<std::string, std::string> named_;   // #<name> -> function name in namedparams
};

// Print a plugin message on stderr when [PYTHON]LOG_LEVEL is at least level.
void PythonHost::log(int level, const std::string &text) const
{
    if (cfg_.log_level >= level) fprintf(stderr, "PythonPlugin: %s\n", text.c_str());
}

// Start Python, extend sys.path and run TOPLEVEL (once per process and script).
bool PythonHost::start(std::string &err)
{
    IniFile ini;
    ini.SetQuiet(true);
    if (!cfg_.ini_file.empty() && ini.Open(cfg_.ini_file)) {
        py_env().debugmask = (int)ini.FindInt("DEBUG", "EMC").value_or(0) | EMC_DEBUG_UNCONDITIONAL;
        py_env().logging_level = (int)ini.FindInt("LOG_LEVEL", "RS274NGC").value_or(0);
    } else {
        py_env().debugmask = EMC_DEBUG_UNCONDITIONAL;
    }
    if (!py_process_start(err) || !py_process_paths(cfg_, err)) return false;
    PyProcess &p = py_process();
    if (!p.toplevel || p.toplevel_path != cfg_.toplevel) {
        GilLock gil;
        Enter enter(interp_);
        if (!py_process_toplevel(cfg_.toplevel, err)) return false;
    }
    log(1, "Python " + std::string(Py_GetVersion()) + ", TOPLEVEL=" + cfg_.toplevel);
    return true;
}

// Module oword / remap / namedparams: the TOPLEVEL namespace's, else sys.modules' (borrowed, may be null).
PyObject *PythonHost::module(PyModuleKind m)
{
    const char *name = MODULE_NAMES[m];
    PyProcess &p = py_process();
    PyObject *ns = p.toplevel ? PyModule_GetDict(p.toplevel.get()) : nullptr;
    PyObject *mod = ns ? PyDict_GetItemString(ns, name) : nullptr;
    if (mod && PyModule_Check(mod)) return mod;
    mod = PyDict_GetItemString(PyImport_GetModuleDict(), name);
    return mod && PyModule_Check(mod) ? mod : nullptr;
}

// module.name when it is callable (new reference), else nullptr with no error pending
PyObject *PythonHost::function(PyModuleKind m, const std::string &name)
{
    PyObject *mod = module(m);
    PyObject *f = mod ? PyObject_GetAttrString(mod, name.c_str()) : nullptr;
    if (!f) PyErr_Clear();
    if (f && !PyCallable_Check(f)) {
        Py_DECREF(f);
        f = nullptr;
    }
    return f;
}

// True when module.name exists and is callable.
bool PythonHost::callable(PyModuleKind m, const std::string &name)
{
    GilLock gil;
    PyRef f(function(m, name));
    return (bool)f;
}

// __init__(self) / __delete__(self) of the TOPLEVEL script, when defined.
PyOutcome PythonHost::call_toplevel(const char *name)
{
    GilLock gil;
    Enter enter(interp_);
    PyProcess &p = py_process();
    PyObject *ns = p.toplevel ? PyModule_GetDict(p.toplevel.get()) : nullptr;
    PyObject *f = ns ? PyDict_GetItemString(ns, name) : nullptr;
    if (!f || !PyCallable_Check(f)) return PyOutcome();
    PyRef r(PyObject_CallOneArg(f, p.self.get()));
    if (!r) return python_error(std::string("TOPLEVEL ") + name);
    return PyOutcome();
}

// RELOAD_ON_CHANGE: run TOPLEVEL again when the file changed.
void PythonHost::reload_if_changed()
{
    if (!cfg_.reload_on_change || !py_process_toplevel_changed()) return;
    PyOutcome o = reload();
    if (o.kind == PyOutcome::ERROR) fprintf(stderr, "%s\n", o.error.c_str());
}

// oword.name(self, *args): a number is the return value, None none, a string an error.
PyOutcome PythonHost::call_oword(const std::string &name, const std::vector<double> &args)
{
    GilLock gil;
    Enter enter(interp_);
    reload_if_changed();
    std::string where = "pycall(oword." + name + ")";
    PyRef f(function(PY_OWORD, name));
    if (!f) return error(where + ": no such function");
    PyRef tuple(PyTuple_New((Py_ssize_t)args.size() + 1));
    Py_INCREF(py_process().self.get());
    PyTuple_SET_ITEM(tuple.get(), 0, py_process().self.get());
    for (size_t k = 0; k < args.size(); k++) PyTuple_SET_ITEM(tuple.get(), k + 1, PyFloat_FromDouble(args[k]));
    PyRef r(PyObject_Call(f.get(), tuple.get(), nullptr));
    if (!r) return python_error(where);
    PyOutcome o;
    if (r.get() == Py_None) return o;
    if (PyUnicode_Check(r.get())) return error(py_str(r.get()));
    if (PyGen_Check(r.get())) return error(where + ": yield INTERP_EXECUTE_FINISH only works in remap functions");
    o.value = PyFloat_AsDouble(r.get());
    if (o.value == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        return error(where + ": returned a " + type_name(r.get()) + "; expected a number, None or a message");
    }
    o.kind = PyOutcome::VALUE;
    return o;
}

// What a remap function (or its generator) ended with: INTERP_OK/None, a message, or an error code.
PyOutcome PythonHost::remap_result(PyObject *r, const std::string &where)
{
    if (r == Py_None) return PyOutcome();
    if (PyUnicode_Check(r)) return error(py_str(r));
    if (!PyLong_Check(r) && !PyFloat_Check(r))
        return error(where + ": returned a " + type_name(r) + "; expected INTERP_OK or a message");
    long code = (long)PyFloat_AsDouble(r);
    if (code == PY_INTERP_EXECUTE_FINISH) InterpAccess::finish_request(interp_) = true;
    if (code < PY_INTERP_MIN_ERROR) return PyOutcome();
    const std::string &msg = InterpAccess::errormsg(interp_);
    return error(msg.empty() ? where + ": returned error code " + std::to_string(code) : msg);
}

// Run a generator to its next yield INTERP_EXECUTE_FINISH (SUSPEND) or to its end.
PyOutcome PythonHost::step(PyObject *gen, const std::string &where)
{
    for (;;) {
        PyObject *value = nullptr;
        PySendResult res = PyIter_Send(gen, Py_None, &value);
        PyRef v(value);
        if (res == PYGEN_ERROR) return python_error(where);
        if (res == PYGEN_RETURN) return remap_result(v.get(), where);
        if (PyUnicode_Check(v.get())) return error(py_str(v.get()));
        if (!PyLong_Check(v.get())) continue;
        long code = PyLong_AsLong(v.get());
        if (code == PY_INTERP_EXECUTE_FINISH) {
            PyOutcome o;
            o.kind = PyOutcome::SUSPEND;
            o.generator = keep_generator(gen);
            return o;
        }
        if (code >= PY_INTERP_MIN_ERROR) return remap_result(v.get(), where);
    }
}

// remap.name(self, **words): prolog, python= body or epilog.
PyOutcome PythonHost::call_remap(const std::string &name, const std::map<std::string, double> &words)
{
    GilLock gil;
    Enter enter(interp_);
    reload_if_changed();
    std::string where = "pycall(remap." + name + ")";
    PyRef f(function(PY_REMAP, name));
    if (!f) return error(where + ": no such function in module remap");
    PyRef kwargs(PyDict_New());
    for (const auto &kv : words) {
        PyRef v(PyFloat_FromDouble(kv.second));
        PyDict_SetItemString(kwargs.get(), kv.first.c_str(), v.get());
    }
    PyRef args(PyTuple_Pack(1, py_process().self.get()));
    InterpAccess::errormsg(interp_).clear();
    PyRef r(PyObject_Call(f.get(), args.get(), kwargs.get()));
    if (!r) return python_error(where);
    if (PyGen_Check(r.get())) return step(r.get(), where);
    return remap_result(r.get(), where);
}

// Continue a generator that yielded INTERP_EXECUTE_FINISH.
PyOutcome PythonHost::resume(const PyGenerator &gen)
{
    GilLock gil;
    Enter enter(interp_);
    PyObject *g = static_cast<PyObject *>(gen.get());
    PyRef qual(PyObject_GetAttrString(g, "__qualname__"));
    if (!qual) PyErr_Clear();
    return step(g, "exception during generator call " + (qual ? py_str(qual.get()) : std::string("?")));
}

// namedparams.<name>(self): the value of #<name>.
PyOutcome PythonHost::named_param(const std::string &name)
{
    GilLock gil;
    Enter enter(interp_);
    auto it = named_.find(name);
    std::string func = it == named_.end() ? name : it->second;
    std::string where = "namedparams." + func;
    PyRef f(function(PY_NAMEDPARAMS, func));
    if (!f) return error(where + ": no such function");
    PyRef r(PyObject_CallOneArg(f.get(), py_process().self.get()));
    if (!r) return python_error(where);
    if (PyUnicode_Check(r.get())) return error(py_str(r.get()));
    PyOutcome o;
    o.value = PyFloat_AsDouble(r.get());
    if (PyBool_Check(r.get()) || (o.value == -1.0 && PyErr_Occurred())) {
        PyErr_Clear();
        return error(where + " returned a " + type_name(r.get()) + "; expected a number");
    }
    o.kind = PyOutcome::VALUE;
    return o;
}

// Callables of module namedparams whose names start with one underscore, as #<names> (lower case).
std::vector<std::string> PythonHost::named_param_names()
{
    GilLock gil;
    std::vector<std::string> names;
    named_.clear();
    PyObject *mod = module(PY_NAMEDPARAMS);
    PyObject *dict = mod ? PyModule_GetDict(mod) : nullptr;
    PyObject *key, *value;
    Py_ssize_t pos = 0;
    while (dict && PyDict_Next(dict, &pos, &key, &value)) {
        std::string n = py_str(key);
        if (n.size() < 2 || n[0] != '_' || n[1] == '_' || !PyCallable_Check(value)) continue;
        std::string lower;
        for (char c : n) lower += (char)tolower((unsigned char)c);
        named_[lower] = n;
        names.push_back(lower);
    }
    return names;
}

// A ;py, statement, run in TOPLEVEL's namespace.
PyOutcome PythonHost::run(const std::string &statement)
{
    GilLock gil;
    Enter enter(interp_);
    reload_if_changed();
    PyObject *ns = PyModule_GetDict(py_process().toplevel.get());
    PyRef r(PyRun_String(statement.c_str(), Py_file_input, ns, ns));
    if (!r) return python_error("py_execute(" + statement + ")");
    return PyOutcome();
}

// ;pyreload: run TOPLEVEL again and reload the oword, remap and namedparams modules.
PyOutcome PythonHost::reload()
{
    GilLock gil;
    Enter enter(interp_);
    std::string err;
    if (!py_process_toplevel(cfg_.toplevel, err)) return error(err);
    PyRef importlib(PyImport_ImportModule("importlib"));
    for (int m = PY_OWORD; importlib && m <= PY_NAMEDPARAMS; m++) {
        PyObject *mod = module((PyModuleKind)m);
        PyRef r(mod ? PyObject_CallMethod(importlib.get(), "reload", "O", mod) : nullptr);
        if (mod && !r) return python_error(std::string("reload ") + MODULE_NAMES[m]);
    }
    log(1, "reloaded " + cfg_.toplevel);
    return PyOutcome();
}

// The factory the plugin table exports.
PyHost *create(Interp &interp, const PythonConfig &cfg, std::string &)
{
    return new PythonHost(interp, cfg);
}

} // namespace

// The process-wide environment the modules read.
PyEnv &py_env()
{
    static PyEnv env;
    return env;
}

// The versioned table the interpreter looks up after loading this plugin.
extern "C" const PyPluginOps rs274ngc_python_plugin = {PY_PLUGIN_VERSION, create};
