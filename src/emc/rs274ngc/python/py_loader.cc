// py_loader.cc: loads the embedded-Python plugin next to librs274ngc and checks its interface version.
#include <cstdlib>
#include <dlfcn.h>

#include "../py_host.hh"

#ifndef PYTHON_LIBSONAME
#error "PYTHON_LIBSONAME (e.g. libpython3.11.so.1.0) must be defined by the build"
#endif

namespace {

constexpr const char *PLUGIN_FILE = "rs274ngc_python.so";
constexpr const char *PLUGIN_SYMBOL = "rs274ngc_python_plugin";

// directory holding this library (lib/), "" when unknown
std::string library_dir()
{
    Dl_info info;
    if (!dladdr(reinterpret_cast<void *>(&load_python_host), &info) || !info.dli_fname) return "";
    std::string path = info.dli_fname;
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

// make the Python C API available: already there inside a Python process, else load libpython
bool ensure_libpython(std::string &err)
{
    if (dlsym(RTLD_DEFAULT, "Py_IsInitialized")) return true;
    if (dlopen(PYTHON_LIBSONAME, RTLD_NOW | RTLD_GLOBAL)) return true;
    err = std::string("cannot load the Python library ") + PYTHON_LIBSONAME + ": " + dlerror();
    return false;
}

// the plugin's exported table, nullptr with err set
const PyPluginOps *open_plugin(std::string &err)
{
    const char *env = getenv("OPENEMC_PYTHON_PLUGIN");
    std::string path = env && *env ? env : library_dir() + "/" + PLUGIN_FILE;
    void *h = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!h) {
        err = "cannot load the Python plugin " + path + ": " + dlerror();
        return nullptr;
    }
    auto ops = static_cast<const PyPluginOps *>(dlsym(h, PLUGIN_SYMBOL));
    if (!ops) {
        err = path + ": no " + PLUGIN_SYMBOL + " table";
        return nullptr;
    }
    if (ops->version != PY_PLUGIN_VERSION) {
        err = path + ": interface version " + std::to_string(ops->version) + ", the interpreter needs " +
              std::to_string(PY_PLUGIN_VERSION);
        return nullptr;
    }
    return ops;
}

} // namespace

// Load the plugin (and libpython when the process has none) and create a host.
std::unique_ptr<PyHost> load_python_host(Interp &interp, const PythonConfig &config, std::string &err)
{
    if (!ensure_libpython(err)) return nullptr;
    const PyPluginOps *ops = open_plugin(err);
    if (!ops) return nullptr;
    return std::unique_ptr<PyHost>(ops->create(interp, config, err));
}
