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

// getstring(sec, var[, num], *, fallback=None) -> str or fallback
PyObject *py_getstring(PyIni *self, PyObject *args, PyObject *kw)
{
    Lookup l;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !parse_lookup(args, kw, l)) return nullptr;
    std::optional<std::string> value = ini->Find(l.var, l.sec, l.num);
    if (!value) return fallback_of(l);
    return PyUnicode_DecodeUTF8(value->data(), Py_ssize_t(value->size()), "surrogateescape");
}

// getbool(...) -> True/False or fallback
PyObject *py_getbool(PyIni *self, PyObject *args, PyObject *kw)
{
    Lookup l;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !parse_lookup(args, kw, l)) return nullptr;
    std::optional<bool> value = ini->FindBool(l.var, l.sec, l.num);
    return value ? PyBool_FromLong(*value) : fallback_of(l);
}

// getsint(...) -> int or fallback
PyObject *py_getsint(PyIni *self, PyObject *args, PyObject *kw)
{
    Lookup l;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !parse_lookup(args, kw, l)) return nullptr;
    std::optional<long long> value = ini->FindInt(l.var, l.sec, l.num);
    return value ? PyLong_FromLongLong(*value) : fallback_of(l);
}

// getuint(...) -> int or fallback
PyObject *py_getuint(PyIni *self, PyObject *args, PyObject *kw)
{
    Lookup l;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !parse_lookup(args, kw, l)) return nullptr;
    std::optional<unsigned long long> value = ini->FindUInt(l.var, l.sec, l.num);
    return value ? PyLong_FromUnsignedLongLong(*value) : fallback_of(l);
}

// getreal(...) -> float or fallback
PyObject *py_getreal(PyIni *self, PyObject *args, PyObject *kw)
{
    Lookup l;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !parse_lookup(args, kw, l)) return nullptr;
    std::optional<double> value = ini->FindReal(l.var, l.sec, l.num);
    return value ? PyFloat_FromDouble(*value) : fallback_of(l);
}

// getlinearunits / getangularunits(...) -> float or fallback
PyObject *py_getunits(PyIni *self, PyObject *args, PyObject *kw, bool linear)
{
    Lookup l;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !parse_lookup(args, kw, l)) return nullptr;
    std::optional<double> value = linear ? ini->FindLinearUnits(l.var, l.sec, l.num)
                                         : ini->FindAngularUnits(l.var, l.sec, l.num);
    return value ? PyFloat_FromDouble(*value) : fallback_of(l);
}

// getlinearunits(sec, var[, num], *, fallback=None) -> units per mm
PyObject *py_getlinearunits(PyIni *self, PyObject *args, PyObject *kw)
{
    return py_getunits(self, args, kw, true);
}

// getangularunits(sec, var[, num], *, fallback=None) -> units per degree
PyObject *py_getangularunits(PyIni *self, PyObject *args, PyObject *kw)
{
    return py_getunits(self, args, kw, false);
}

// getjointtype(...) -> 1 (LINEAR), 2 (ANGULAR) or fallback
PyObject *py_getjointtype(PyIni *self, PyObject *args, PyObject *kw)
{
    Lookup l;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !parse_lookup(args, kw, l)) return nullptr;
    std::optional<int> value = ini->FindJointType(l.var, l.sec, l.num);
    return value ? PyLong_FromLong(*value) : fallback_of(l);
}

// map*(enumstr, *, fallback=None): which = 0 linear, 1 angular, 2 joint type.
PyObject *map_enum(PyObject *args, PyObject *kw, int which)
{
    static const char *kwlist[] = {"", "fallback", nullptr};
    const char *text = nullptr;
    PyObject *fallback = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "s|$O", const_cast<char **>(kwlist), &text,
                                     &fallback))
        return nullptr;
    if (which == 2) {
        std::optional<int> type = IniFile::MapJointType(text);
        if (type) return PyLong_FromLong(*type);
    } else {
        std::optional<double> units = which == 0 ? IniFile::MapLinearUnits(text)
                                                 : IniFile::MapAngularUnits(text);
        if (units) return PyFloat_FromDouble(*units);
    }
    Py_INCREF(fallback);
    return fallback;
}

// maplinearunits(enumstr, *, fallback=None) -> units per mm
PyObject *py_maplinearunits(PyObject *, PyObject *args, PyObject *kw)
{
    return map_enum(args, kw, 0);
}

// mapangularunits(enumstr, *, fallback=None) -> units per degree
PyObject *py_mapangularunits(PyObject *, PyObject *args, PyObject *kw)
{
    return map_enum(args, kw, 1);
}

// mapjointtype(enumstr, *, fallback=None) -> 1 or 2
PyObject *py_mapjointtype(PyObject *, PyObject *args, PyObject *kw)
{
    return map_enum(args, kw, 2);
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
    LOOKUP("getstring", py_getstring, "getstring(sec, var[, num], *, fallback=None) -> str"),
    LOOKUP("find", py_getstring, "alias of getstring"),
    LOOKUP("getbool", py_getbool, "getbool(sec, var[, num], *, fallback=None) -> bool"),
    LOOKUP("getsint", py_getsint, "getsint(sec, var[, num], *, fallback=None) -> int"),
    LOOKUP("getint", py_getsint, "alias of getsint"),
    LOOKUP("getuint", py_getuint, "getuint(sec, var[, num], *, fallback=None) -> int"),
    LOOKUP("getreal", py_getreal, "getreal(sec, var[, num], *, fallback=None) -> float"),
    LOOKUP("getfloat", py_getreal, "alias of getreal"),
    LOOKUP("getlinearunits", py_getlinearunits, "LINEAR_UNITS value as units per mm"),
    LOOKUP("getangularunits", py_getangularunits, "ANGULAR_UNITS value as units per degree"),
    LOOKUP("getjointtype", py_getjointtype, "joint TYPE: 1 LINEAR, 2 ANGULAR"),
    LOOKUP_STATIC("maplinearunits", py_maplinearunits, "maplinearunits(str, *, fallback=None)"),
    LOOKUP_STATIC("mapangularunits", py_mapangularunits, "mapangularunits(str, *, fallback=None)"),
    LOOKUP_STATIC("mapjointtype", py_mapjointtype, "mapjointtype(str, *, fallback=None)"),
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

PyType_Spec ini_spec = {"_linuxcnc_ini.ini", sizeof(PyIni), 0, Py_TPFLAGS_DEFAULT, ini_slots};

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
    ini_py_error = PyErr_NewException("_linuxcnc_ini.error", PyExc_RuntimeError, nullptr);
    if (!type || !ini_py_error || PyModule_AddObjectRef(module, "error", ini_py_error) < 0 ||
        PyModule_AddObjectRef(module, "ini", type) < 0) {
        Py_XDECREF(type);
        Py_DECREF(module);
        return nullptr;
    }
    Py_DECREF(type);
    return module;
}
