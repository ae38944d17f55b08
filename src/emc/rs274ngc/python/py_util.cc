// py_util.cc: exception text, output flushing and string conversion for the embedded-Python plugin.
#include "py_util.hh"

#include <cstdio>

// The pending Python exception as text: traceback lines then "Type: message"; clears it.
std::string py_error_text()
{
    PyObject *type = nullptr, *value = nullptr, *tb = nullptr;
    PyErr_Fetch(&type, &value, &tb);
    if (!type) return "unknown Python error";
    PyErr_NormalizeException(&type, &value, &tb);
    PyRef t(type), v(value), b(tb);
    std::string text;
    PyRef mod(PyImport_ImportModule("traceback"));
    PyRef lines(mod ? PyObject_CallMethod(mod.get(), "format_exception", "OOO", type,
                                          value ? value : Py_None, tb ? tb : Py_None)
                    : nullptr);
    if (lines && PyList_Check(lines.get())) {
        for (Py_ssize_t i = 0; i < PyList_GET_SIZE(lines.get()); i++)
            text += py_str(PyList_GET_ITEM(lines.get(), i));
    } else {
        PyErr_Clear();
        PyRef s(PyObject_Str(value ? value : type));
        text = s ? py_str(s.get()) : "unprintable Python error";
    }
    while (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
}

// Flush C stdio before Python prints, so output keeps its order.
void flush_c_output()
{
    fflush(stdout);
    fflush(stderr);
}

// Flush Python's sys.stdout and sys.stderr after it ran.
void flush_py_output()
{
    PyObject *type = nullptr, *value = nullptr, *tb = nullptr;
    PyErr_Fetch(&type, &value, &tb);
    for (const char *name : {"stdout", "stderr"}) {
        PyObject *stream = PySys_GetObject(name);
        if (!stream || stream == Py_None) continue;
        PyRef r(PyObject_CallMethod(stream, "flush", nullptr));
        if (!r) PyErr_Clear();
    }
    PyErr_Restore(type, value, tb);
}

// A Python str as UTF-8 std::string ("" when not a str).
std::string py_str(PyObject *o)
{
    if (!o || !PyUnicode_Check(o)) return "";
    Py_ssize_t n = 0;
    const char *s = PyUnicode_AsUTF8AndSize(o, &n);
    if (!s) {
        PyErr_Clear();
        return "";
    }
    return std::string(s, (size_t)n);
}
