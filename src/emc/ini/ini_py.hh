// ini_py.hh: shared declarations of the _linuxcnc_ini Python module's source files.
#ifndef OPENEMC_INI_PY_HH
#define OPENEMC_INI_PY_HH

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "inifile.hh"

// A Python `ini` object.
struct PyIni {
    PyObject_HEAD
    IniFile *ini;
};

// _linuxcnc_ini.error
extern PyObject *ini_py_error;
// The parsed file of an object, or nullptr with an exception set.
const IniFile *ini_py_file(PyIni *self);
// getsections() / getvariables([sec]) / findall(sec[, var]) / lineof(sec, var[, num]).
PyObject *ini_py_getsections(PyIni *self, PyObject *args);
PyObject *ini_py_getvariables(PyIni *self, PyObject *args);
PyObject *ini_py_findall(PyIni *self, PyObject *args);
PyObject *ini_py_lineof(PyIni *self, PyObject *args);

#endif
