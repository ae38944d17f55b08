// py_state_blocks.cc: blocks, call contexts, tool-table rows and remap definitions as Python dicts.
#include <cctype>

#include "interp_access.hh"
#include "py_plugin.hh"
#include "py_state.hh"

namespace {

// O-call arguments a block carries (LinuxCNC's INTERP_SUB_PARAMS).
constexpr int SUB_PARAMS = 30;

// d[key] = value, consuming the value reference
void put(PyObject *d, const char *key, PyObject *value)
{
    if (!value) {
        PyErr_Clear();
        return;
    }
    PyDict_SetItemString(d, key, value);
    Py_DECREF(value);
}

// letters whose value LinuxCNC keeps as an integer
bool int_letter(char c)
{
    return c == 'l' || c == 't' || c == 'h';
}

// x_flag / x_number for every word letter
void put_letters(PyObject *d, const Block &b)
{
    for (char c = 'a'; c <= 'z'; c++) {
        if (c == 'g' || c == 'm' || c == 'n' || c == 'o') continue;
        std::string flag = std::string(1, c) + "_flag", number = std::string(1, c) + "_number";
        double v = b.has[c - 'a'] ? b.val[c - 'a'] : 0.0;
        put(d, flag.c_str(), PyBool_FromLong(b.has[c - 'a']));
        put(d, number.c_str(), int_letter(c) ? PyLong_FromLong((long)v) : PyFloat_FromDouble(v));
    }
    put(d, "d_number_float", PyFloat_FromDouble(b.has['d' - 'a'] ? b.val['d' - 'a'] : 0.0));
}

// a tuple of ints
PyObject *int_tuple(const int *v, int n)
{
    PyObject *t = PyTuple_New(n);
    for (int k = 0; t && k < n; k++) PyTuple_SET_ITEM(t, k, PyLong_FromLong(v[k]));
    return t;
}

// value or None
PyObject *opt_name(const std::string &s)
{
    if (s.empty()) Py_RETURN_NONE;
    return PyUnicode_FromString(s.c_str());
}

} // namespace

// A REMAP definition as a dict (LinuxCNC's remap_struct field names).
PyObject *remap_dict(const RemapDef &r)
{
    PyObject *d = PyDict_New();
    if (!d) return nullptr;
    std::string name;
    for (char c : r.code) name += (char)tolower((unsigned char)c);
    put(d, "name", PyUnicode_FromString(name.c_str()));
    put(d, "argspec", PyUnicode_FromString(r.argspec.c_str()));
    put(d, "modal_group", PyLong_FromLong(r.group));
    put(d, "motion_code", PyLong_FromLong(r.letter == 'G' ? r.number : -1));
    put(d, "prolog_func", opt_name(r.prolog));
    put(d, "remap_py", opt_name(r.python));
    put(d, "remap_ngc", opt_name(r.ngc));
    put(d, "epilog_func", opt_name(r.epilog));
    return d;
}

// A block as a dict: word letters, modal codes, comment, O-word name and call arguments.
PyObject *block_dict(const Block &b, const RemapDef *executing)
{
    PyObject *d = PyDict_New();
    if (!d) return nullptr;
    put_letters(d, b);
    put(d, "line_number", PyLong_FromLong(b.has_line_number ? (long)b.line_number : -1));
    put(d, "comment", PyUnicode_FromString(b.comment.c_str()));
    put(d, "o_name", PyUnicode_FromString(b.o_name.c_str()));
    put(d, "o_type", PyLong_FromLong(b.o_kind));
    put(d, "g_modes", int_tuple(b.g_modes, GG_COUNT));
    put(d, "m_modes", int_tuple(b.m_modes, MG_COUNT));
    put(d, "m_count", PyLong_FromLong(b.m_count));
    put(d, "motion_to_be", PyLong_FromLong(b.motion()));
    PyObject *params = PyTuple_New(SUB_PARAMS);
    for (int k = 0; params && k < SUB_PARAMS; k++)
        PyTuple_SET_ITEM(params, k, PyFloat_FromDouble(k < (int)b.o_args.size() ? b.o_args[k] : 0.0));
    put(d, "params", params);
    put(d, "radius_flag", PyBool_FromLong(b.has_polar_radius));
    put(d, "radius", PyFloat_FromDouble(b.polar_radius));
    put(d, "theta_flag", PyBool_FromLong(b.has_polar_angle));
    put(d, "theta", PyFloat_FromDouble(b.polar_angle));
    put(d, "dollar_flag", PyBool_FromLong(b.has_dollar));
    put(d, "dollar_number", PyFloat_FromDouble(b.dollar));
    if (executing) {
        put(d, "executing_remap", remap_dict(*executing));
    } else {
        Py_INCREF(Py_None);
        put(d, "executing_remap", Py_None);
    }
    return d;
}
