// ini_py.cc: Python module _linuxcnc_ini: the `ini` type of python.md (linuxcnc.ini) over the C++ INI library.
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "ini_py.hh"

#include <string>

PyObject *ini_py_error;

namespace {

// Arguments shared by the lookups: (sec, var[, num], *, fallback=None).
struct Lookup {
    const char *sec = nullptr;
    const char *var = nullptr;
    int num = 1;
    PyObject *fallback = Py_None;
};

// Parse lookup arguments; num is positional only, fallback keyword only.
bool parse_lookup(PyObject *args, PyObject *kw, Lookup &l)
{
    static const char *kwlist[] = {"", "", "", "fallback", nullptr};
    return PyArg_ParseTupleAndKeywords(args, kw, "ss|i$O", const_cast<char **>(kwlist), &l.sec,
                                       &l.var, &l.num, &l.fallback);
}

// Return the fallback (new reference).
PyObject *fallback_of(const Lookup &l)
{
    Py_INCREF(l.fallback);
    return l.fallback;
}

// ini(filename): parse the file or raise error.
int ini_init(PyIni *self, PyObject *args, PyObject *)
{
    const char *path = nullptr;
    if (!PyArg_ParseTuple(args, "s", &path)) return -1;
    delete self->ini;
    self->ini = new IniFile();
    if (!self->ini->Open(path)) {
        PyErr_Format(ini_py_error, "inifile.open(%s) failed", path);
        return -1;
    }
    return 0;
}

// Free the parsed file.
void ini_dealloc(PyIni *self)
{
    PyTypeObject *type = Py_TYPE(self);
    delete self->ini;
    type->tp_free(reinterpret_cast<PyObject *>(self));
    Py_DECREF(type);
}

// hassection(sec) -> bool
PyObject *py_hassection(PyIni *self, PyObject *args)
{
    const char *sec = nullptr;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !PyArg_ParseTuple(args, "s", &sec)) return nullptr;
    return PyBool_FromLong(ini->HasSection(sec));
}

// hasvariable(sec, var[, num]) -> bool
PyObject *py_hasvariable(PyIni *self, PyObject *args)
{
    const char *sec = nullptr, *var = nullptr;
    int num = 1;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !PyArg_ParseTuple(args, "ss|i", &sec, &var, &num)) return nullptr;
    return PyBool_FromLong(ini->FindEntry(var, sec, num) != nullptr);
}

// A Python str of raw INI text (undecodable bytes kept as surrogates).
PyObject *to_py(const std::string &value)
{
    return PyUnicode_DecodeUTF8(value.data(), Py_ssize_t(value.size()), "surrogateescape");
}

// A Python bool.
PyObject *to_py(bool value)
{
    return PyBool_FromLong(value);
}

// A Python int of a signed value.
PyObject *to_py(long long value)
{
    return PyLong_FromLongLong(value);
}

// A Python int of an unsigned value.
PyObject *to_py(unsigned long long value)
{
    return PyLong_FromUnsignedLongLong(value);
}

// A Python int of an enum value.
PyObject *to_py(int value)
{
    return PyLong_FromLong(value);
}

// A Python float.
PyObject *to_py(double value)
{
    return PyFloat_FromDouble(value);
}

// A typed lookup method: (sec, var[, num], *, fallback=None) -> value through Find, or fallback.
template <typename T,
          std::optional<T> (IniFile::*Find)(const std::string &, const std::string &, int) const>
PyObject *py_lookup(PyIni *self, PyObject *args, PyObject *kw)
{
    Lookup l;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !parse_lookup(args, kw, l)) return nullptr;
    std::optional<T> value = (ini->*Find)(l.var, l.sec, l.num);
    return value ? to_py(*value) : fallback_of(l);
}

// map*(enumstr, *, fallback=None): the value Map gives the word, or fallback.
template <typename T, std::optional<T> (*Map)(const std::string &)>
PyObject *py_map(PyObject *, PyObject *args, PyObject *kw)
{
    static const char *kwlist[] = {"", "fallback", nullptr};
    const char *text = nullptr;
    PyObject *fallback = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "s|$O", const_cast<char **>(kwlist), &text,
                                     &fallback))
        return nullptr;
    std::optional<T> value = Map(text);
    if (value) return to_py(*value);
    Py_INCREF(fallback);
    return fallback;
}

// Method table entries: lookups take keywords (fallback=), the rest positional arguments only.
#define LOOKUP(name, fn, doc) \
    {name, reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(fn)), \
     METH_VARARGS | METH_KEYWORDS, doc}
#define LOOKUP_STATIC(name, fn, doc) \
    {name, reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(fn)), \
     METH_VARARGS | METH_KEYWORDS | METH_STATIC, doc}
#define PLAIN(name, fn, doc) \
    {name, reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(fn)), METH_VARARGS, doc}

PyMethodDef ini_methods[] = {
    PLAIN("hassection", py_hassection, "hassection(sec) -> bool"),
    PLAIN("hasvariable", py_hasvariable, "hasvariable(sec, var[, num]) -> bool"),
    LOOKUP("getstring", (py_lookup<std::string, &IniFile::Find>),
           "getstring(sec, var[, num], *, fallback=None) -> str"),
    LOOKUP("find", (py_lookup<std::string, &IniFile::Find>), "alias of getstring"),
    LOOKUP("getbool", (py_lookup<bool, &IniFile::FindBool>),
           "getbool(sec, var[, num], *, fallback=None) -> bool"),
    LOOKUP("getsint", (py_lookup<long long, &IniFile::FindInt>),
           "getsint(sec, var[, num], *, fallback=None) -> int"),
    LOOKUP("getint", (py_lookup<long long, &IniFile::FindInt>), "alias of getsint"),
    LOOKUP("getuint", (py_lookup<unsigned long long, &IniFile::FindUInt>),
           "getuint(sec, var[, num], *, fallback=None) -> int"),
    LOOKUP("getreal", (py_lookup<double, &IniFile::FindReal>),
           "getreal(sec, var[, num], *, fallback=None) -> float"),
    LOOKUP("getfloat", (py_lookup<double, &IniFile::FindReal>), "alias of getreal"),
    LOOKUP("getlinearunits", (py_lookup<double, &IniFile::FindLinearUnits>),
           "LINEAR_UNITS value as units per mm"),
    LOOKUP("getangularunits", (py_lookup<double, &IniFile::FindAngularUnits>),
           "ANGULAR_UNITS value as units per degree"),
    LOOKUP("getjointtype", (py_lookup<int, &IniFile::FindJointType>),
           "joint TYPE: 1 LINEAR, 2 ANGULAR"),
    LOOKUP_STATIC("maplinearunits", (py_map<double, IniFile::MapLinearUnits>),
                  "maplinearunits(str, *, fallback=None)"),
    LOOKUP_STATIC("mapangularunits", (py_map<double, IniFile::MapAngularUnits>),
                  "mapangularunits(str, *, fallback=None)"),
    LOOKUP_STATIC("mapjointtype", (py_map<int, IniFile::MapJointType>),
                  "mapjointtype(str, *, fallback=None)"),
    PLAIN("getsections", ini_py_getsections, "getsections() -> list of section names"),
    PLAIN("getvariables", ini_py_getvariables, "getvariables([sec]) -> list of (name, value)"),
    PLAIN("findall", ini_py_findall, "findall(sec[, var]) -> list of values"),
    PLAIN("lineof", ini_py_lineof, "lineof(sec, var[, num]) -> (filename, lineno)"),
    {nullptr, nullptr, 0, nullptr},
};

PyType_Slot ini_slots[] = {
    {Py_tp_init, reinterpret_cast<void *>(ini_init)},
    {Py_tp_dealloc, reinterpret_cast<void *>(ini_dealloc)},
    {Py_tp_new, reinterpret_cast<void *>(PyType_GenericNew)},
    {Py_tp_methods, ini_methods},
    {Py_tp_doc, const_cast<char *>("ini(filename): a parsed INI file")},
    {0, nullptr},
};

PyType_Spec ini_spec = {"linuxcnc.ini", sizeof(PyIni), 0, Py_TPFLAGS_DEFAULT, ini_slots};

PyModuleDef ini_module = {PyModuleDef_HEAD_INIT, "_linuxcnc_ini",
                          "INI file access (the ini type of the linuxcnc module)", -1,
                          nullptr, nullptr, nullptr, nullptr, nullptr};

} // namespace

// The IniFile of an object, or nullptr (with an exception) when __init__ did not succeed.
const IniFile *ini_py_file(PyIni *self)
{
    if (!self->ini || !self->ini->IsOpen()) {
        PyErr_SetString(ini_py_error, "ini file not open");
        return nullptr;
    }
    return self->ini;
}

// Module init: the `ini` type and the `error` exception.
PyMODINIT_FUNC PyInit__linuxcnc_ini(void)
{
    PyObject *module = PyModule_Create(&ini_module);
    if (!module) return nullptr;
    PyObject *type = PyType_FromSpec(&ini_spec);
    ini_py_error = PyErr_NewException("linuxcnc.error", PyExc_RuntimeError, nullptr);
    if (!type || !ini_py_error || PyModule_AddObjectRef(module, "error", ini_py_error) < 0 ||
        PyModule_AddObjectRef(module, "ini", type) < 0) {
        Py_XDECREF(type);
        Py_DECREF(module);
        return nullptr;
    }
    Py_DECREF(type);
    return module;
}
