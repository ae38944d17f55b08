// lcnc_module.cc: the Python `linuxcnc` module: attributes (nmlfile, PREFIX, SHARE, version, error), constants, the ini type, channel links.
#include "lcnc_py.hh"

#include <dlfcn.h>

#include <cerrno>
#include <cstring>

PyObject *lcnc_module = nullptr;
PyObject *lcnc_error = nullptr;

// Version of the LinuxCNC Python API this module implements.
static const char LCNC_API_VERSION[] = "2.10.0~pre1";
static const char OPENEMC_VERSION[] = "0.1";

// ---- channel links

LcncLink::LcncLink(const char *buffer) : buffer_(buffer)
{
    PyObject *file = PyObject_GetAttrString(lcnc_module, "nmlfile");
    if (file && PyUnicode_Check(file)) {
        const char *text = PyUnicode_AsUTF8(file);
        if (text) nml_file_ = text;
    }
    Py_XDECREF(file);
    PyErr_Clear();
    if (nml_file_.empty()) nml_file_ = emc_default_nml_file();
}

// Attach when not attached or when the buffer was removed.
bool LcncLink::ready()
{
    if (channel_ && channel_->alive()) return true;
    channel_.reset();
    channel_ = EmcChannel::open(nml_file_, buffer_, "xemc", &error_);
    return channel_ != nullptr;
}

// Peek the status buffer into out, checking that it is an EMC_STAT.
int lcnc_peek_status(LcncLink &link, EMC_STAT &out)
{
    int n = nml_peek(link.raw(), &out, sizeof out);
    if (n == 0) return 0;
    std::string why;
    if (n < 0 || emc_msg_check(&out, static_cast<size_t>(n), &why) < 0 ||
        out.type != EMC_STAT_TYPE) {
        if (n < 0) why = strerror(-n);
        else if (why.empty()) why = std::string("found ") + emc_symbol_lookup(out.type);
        PyErr_Format(lcnc_error, "emcStatus: not a status message: %s", why.c_str());
        return -1;
    }
    return 1;
}

// ---- helpers for attribute conversion

// Python str of a text field.
PyObject *lcnc_text(const char *field, size_t size)
{
    return PyUnicode_DecodeFSDefaultAndSize(field, static_cast<Py_ssize_t>(strnlen(field, size)));
}

// 9-tuple of a pose.
PyObject *lcnc_pose_tuple(const EmcPose &p)
{
    return Py_BuildValue("(ddddddddd)", p.tran.x, p.tran.y, p.tran.z, p.a, p.b, p.c, p.u, p.v,
                         p.w);
}

// ---- module attributes

// Top of the tree or install prefix: $EMC2_HOME, else two levels above this module.
static std::string prefix_dir()
{
    const char *home = getenv("EMC2_HOME");
    if (home && *home) return home;
    Dl_info info;
    if (!dladdr(reinterpret_cast<void *>(&prefix_dir), &info) || !info.dli_fname) return "/usr";
    std::string path = info.dli_fname;
    for (int up = 0; up < 3; up++) {
        size_t slash = path.rfind('/');
        if (slash == std::string::npos) return "/usr";
        path.resize(slash);
    }
    return path.empty() ? "/" : path;
}

// nmlfile, PREFIX, SHARE, version, openemc_version.
static int add_attributes(PyObject *m)
{
    std::string prefix = prefix_dir();
    if (PyModule_AddStringConstant(m, "nmlfile", emc_default_nml_file().c_str()) < 0 ||
        PyModule_AddStringConstant(m, "PREFIX", prefix.c_str()) < 0 ||
        PyModule_AddStringConstant(m, "SHARE", (prefix + "/share").c_str()) < 0 ||
        PyModule_AddStringConstant(m, "version", LCNC_API_VERSION) < 0 ||
        PyModule_AddStringConstant(m, "openemc_version", OPENEMC_VERSION) < 0)
        return -1;
    return 0;
}

// linuxcnc.ini and linuxcnc.error come from _linuxcnc_ini, so ini errors are linuxcnc.error.
static int add_ini(PyObject *m)
{
    PyObject *ini_module = PyImport_ImportModule("_linuxcnc_ini");
    if (!ini_module) return -1;
    PyObject *ini = PyObject_GetAttrString(ini_module, "ini");
    lcnc_error = PyObject_GetAttrString(ini_module, "error");
    Py_DECREF(ini_module);
    if (!ini || !lcnc_error || PyModule_AddObjectRef(m, "ini", ini) < 0 ||
        PyModule_AddObjectRef(m, "error", lcnc_error) < 0) {
        Py_XDECREF(ini);
        return -1;
    }
    Py_DECREF(ini);
    return 0;
}

static PyModuleDef lcnc_module_def = {
    PyModuleDef_HEAD_INIT, "linuxcnc",
    "Talk to the controller: status (stat), commands (command), operator messages "
    "(error_channel), INI files (ini), backplot (positionlogger).",
    -1, nullptr, nullptr, nullptr, nullptr, nullptr};

// Module init.
PyMODINIT_FUNC PyInit_linuxcnc(void)
{
    PyObject *m = PyModule_Create(&lcnc_module_def);
    if (!m) return nullptr;
    lcnc_module = m;
    if (add_ini(m) < 0 || add_attributes(m) < 0 || lcnc_add_constants(m) < 0 ||
        lcnc_add_tool(m) < 0 || lcnc_add_stat(m) < 0 || lcnc_add_command(m) < 0 ||
        lcnc_add_error_channel(m) < 0 || lcnc_add_logger(m) < 0 || lcnc_add_preview(m) < 0) {
        lcnc_module = nullptr;
        Py_DECREF(m);
        return nullptr;
    }
    return m;
}
