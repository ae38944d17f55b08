// py_start.cc: starting the embedded Python once per process: the runtime, sys.path, the interpreter and
// emccanon modules, and the TOPLEVEL script's namespace.
#include <dlfcn.h>
#include <sys/stat.h>

#include "py_plugin.hh"
#include "py_start.hh"

namespace {

// directory of this plugin (lib/), "." when unknown
std::string plugin_dir()
{
    Dl_info info;
    if (!dladdr(reinterpret_cast<void *>(&py_process), &info) || !info.dli_fname) return ".";
    std::string path = info.dli_fname;
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

// true when sys.path already holds dir
bool on_path(PyObject *path, const std::string &dir)
{
    PyRef d(PyUnicode_FromString(dir.c_str()));
    return d && PySequence_Contains(path, d.get()) == 1;
}

// put dir into sys.path at index (or at the end with index < 0) unless it is there
bool add_path(const std::string &dir, Py_ssize_t index)
{
    PyObject *path = PySys_GetObject("path");
    if (!path || !PyList_Check(path)) return false;
    if (on_path(path, dir)) return true;
    PyRef d(PyUnicode_FromString(dir.c_str()));
    if (!d) return false;
    return (index < 0 ? PyList_Append(path, d.get()) : PyList_Insert(path, index, d.get())) == 0;
}

// sys.modules[name] = module
bool register_module(const char *name, PyObject *module)
{
    PyObject *modules = PyImport_GetModuleDict();
    return module && PyDict_SetItemString(modules, name, module) == 0;
}

// load lib/python/rs274ngc_embed/interpreter.py as module "interpreter"
PyObject *load_interpreter_py(const std::string &lib_python)
{
    std::string file = lib_python + "/rs274ngc_embed/interpreter.py";
    PyRef util(PyImport_ImportModule("importlib.util"));
    if (!util) return nullptr;
    PyRef spec(PyObject_CallMethod(util.get(), "spec_from_file_location", "ss", "interpreter", file.c_str()));
    if (!spec || spec.get() == Py_None) {
        if (!PyErr_Occurred()) PyErr_Format(PyExc_ImportError, "cannot load %s", file.c_str());
        return nullptr;
    }
    PyRef mod(PyObject_CallMethod(util.get(), "module_from_spec", "O", spec.get()));
    if (!mod || !register_module("interpreter", mod.get())) return nullptr;
    PyRef loader(PyObject_GetAttrString(spec.get(), "loader"));
    PyRef done(loader ? PyObject_CallMethod(loader.get(), "exec_module", "O", mod.get()) : nullptr);
    return done ? mod.release() : nullptr;
}

// modification time of a file, 0 when it cannot be read
time_t mtime(const std::string &path)
{
    struct stat st;
    return stat(path.c_str(), &st) == 0 ? st.st_mtime : 0;
}

} // namespace

// The process-wide Python state.
PyProcess &py_process()
{
    static PyProcess *p = new PyProcess;   // never destroyed: Python may be finalized before static destructors run
    return *p;
}

// Start the runtime (when the process has none) and the modules; false with err set.
bool py_process_start(std::string &err)
{
    PyProcess &p = py_process();
    if (!Py_IsInitialized()) {
        Py_InitializeEx(0);
        p.embedded = true;
        PyEval_SaveThread();
    }
    GilLock gil;
    if (p.ready) return true;
    if (p.embedded) {   // code that reads sys.argv (argparse, GUI toolkits) finds one
        PyRef argv(Py_BuildValue("[s]", ""));
        if (!argv || PySys_SetObject("argv", argv.get()) != 0) PyErr_Clear();
    }
    std::string lib_python = plugin_dir() + "/python";
    PyRef state(make_state_module()), canon(make_canon_module());
    bool ok = add_path(lib_python, -1) && register_module("_rs274ngc", state.get()) &&
              register_module("emccanon", canon.get());
    PyRef interp(ok ? load_interpreter_py(lib_python) : nullptr);
    PyRef self(interp ? PyObject_GetAttrString(interp.get(), "this") : nullptr);
    if (!self) {
        err = "cannot set up the interpreter module:\n" + py_error_text();
        return false;
    }
    p.interpreter = interp;
    p.self = self;
    p.ready = true;
    return true;
}

// Put the [PYTHON] PATH_PREPEND / PATH_APPEND directories on sys.path; false with err set.
bool py_process_paths(const PythonConfig &cfg, std::string &err)
{
    GilLock gil;
    Py_ssize_t index = 0;
    for (const std::string &d : cfg.path_prepend)
        if (!add_path(d, index++)) err = "cannot add " + d + " to sys.path";
    for (const std::string &d : cfg.path_append)
        if (!add_path(d, -1)) err = "cannot add " + d + " to sys.path";
    return err.empty();
}

// The namespace TOPLEVEL runs in: __main__ of an embedding process, a private module inside a Python program.
static PyObject *fresh_namespace(const std::string &path)
{
    PyProcess &p = py_process();
    PyRef mod(p.embedded ? PyImport_AddModule("__main__") : PyModule_New("__rs274ngc_toplevel__"));
    if (p.embedded) Py_XINCREF(mod.get());
    if (!mod) return nullptr;
    PyObject *ns = PyModule_GetDict(mod.get());
    PyRef file(PyUnicode_FromString(path.c_str()));
    if (!ns || !file || PyDict_SetItemString(ns, "__file__", file.get()) != 0) return nullptr;
    if (PyDict_SetItemString(ns, "this", p.self.get()) != 0) return nullptr;
    if (!PyDict_GetItemString(ns, "__builtins__") &&
        PyDict_SetItemString(ns, "__builtins__", PyEval_GetBuiltins()) != 0)
        return nullptr;
    return mod.release();
}

// Run the TOPLEVEL script (path "" = none: an empty namespace for ;py, statements); false with err set.
bool py_process_toplevel(const std::string &path, std::string &err)
{
    GilLock gil;
    PyProcess &p = py_process();
    PyRef mod(fresh_namespace(path));
    if (!mod) {
        err = py_error_text();
        return false;
    }
    p.toplevel = mod;
    p.toplevel_path = path;
    p.toplevel_mtime = path.empty() ? 0 : mtime(path);
    if (path.empty()) return true;
    FILE *f = fopen(path.c_str(), "r");
    if (!f) {
        err = "[PYTHON]TOPLEVEL=" + path + ": cannot open the file";
        return false;
    }
    PyObject *ns = PyModule_GetDict(mod.get());
    PyRef r(PyRun_FileEx(f, path.c_str(), Py_file_input, ns, ns, 1));
    if (!r) {
        err = "[PYTHON]TOPLEVEL=" + path + " failed:\n" + py_error_text();
        return false;
    }
    return true;
}

// True when TOPLEVEL changed on disk since it ran (RELOAD_ON_CHANGE).
bool py_process_toplevel_changed()
{
    PyProcess &p = py_process();
    return !p.toplevel_path.empty() && mtime(p.toplevel_path) != p.toplevel_mtime;
}
