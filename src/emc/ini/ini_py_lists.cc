// ini_py_lists.cc: list-returning methods of the Python `ini` type (sections, variables, findall, lineof).
#include "ini_py.hh"

#include <string>

namespace {

// A Python str from a value (bytes that are not UTF-8 are kept via surrogateescape).
PyObject *to_str(const std::string &text)
{
    return PyUnicode_DecodeUTF8(text.data(), Py_ssize_t(text.size()), "surrogateescape");
}

// Append a new reference to a list, dropping our reference; false on failure.
bool append_new(PyObject *list, PyObject *item)
{
    if (!item) return false;
    int rc = PyList_Append(list, item);
    Py_DECREF(item);
    return rc == 0;
}

// Build a list of str from strings.
PyObject *str_list(const std::vector<std::string> &items)
{
    PyObject *list = PyList_New(0);
    for (const std::string &item : items) {
        if (list && !append_new(list, to_str(item))) Py_CLEAR(list);
    }
    return list;
}

} // namespace

// getsections() -> [name, ...] in file order.
PyObject *ini_py_getsections(PyIni *self, PyObject *args)
{
    const IniFile *ini = ini_py_file(self);
    if (!ini || !PyArg_ParseTuple(args, "")) return nullptr;
    return str_list(ini->Sections());
}

// getvariables([sec]) -> [(name, value), ...]; no section = all sections.
PyObject *ini_py_getvariables(PyIni *self, PyObject *args)
{
    const char *sec = "";
    const IniFile *ini = ini_py_file(self);
    if (!ini || !PyArg_ParseTuple(args, "|s", &sec)) return nullptr;
    PyObject *list = PyList_New(0);
    if (*sec && !ini->HasSection(sec)) return list;
    for (const auto &kv : ini->Variables(sec)) {
        PyObject *key = to_str(kv.first), *value = to_str(kv.second);
        PyObject *pair = key && value ? PyTuple_Pack(2, key, value) : nullptr;
        Py_XDECREF(key);
        Py_XDECREF(value);
        if (list && !append_new(list, pair)) Py_CLEAR(list);
    }
    return list;
}

// findall(sec[, var]) -> [value, ...]; var omitted or "" = every value of the section.
PyObject *ini_py_findall(PyIni *self, PyObject *args)
{
    const char *sec = nullptr, *var = nullptr;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !PyArg_ParseTuple(args, "s|s", &sec, &var)) return nullptr;
    if (var && *var) return str_list(ini->FindAll(var, sec));
    std::vector<std::string> values;
    if (*sec && !ini->HasSection(sec)) return str_list(values);
    for (const auto &kv : ini->Variables(sec)) values.push_back(kv.second);
    return str_list(values);
}

// lineof(sec, var[, num]) -> (filename, lineno) or (None, None).
PyObject *ini_py_lineof(PyIni *self, PyObject *args)
{
    const char *sec = nullptr, *var = nullptr;
    int num = 1;
    const IniFile *ini = ini_py_file(self);
    if (!ini || !PyArg_ParseTuple(args, "ss|i", &sec, &var, &num)) return nullptr;
    const IniEntry *entry = ini->FindEntry(var, sec, num);
    if (!entry) return Py_BuildValue("(OO)", Py_None, Py_None);
    return Py_BuildValue("(Ni)", to_str(entry->file), entry->line);
}
