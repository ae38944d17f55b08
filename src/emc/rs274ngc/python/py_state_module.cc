// py_state_module.cc: the private module `_rs274ngc` that interpreter.py builds `self`, params, blocks,
// contexts and the tool table on.
#include <cctype>
#include <cstring>
#include <set>

#include "interp_access.hh"
#include "py_plugin.hh"
#include "py_state.hh"

namespace {

// Numbered parameters and call arguments a context saves (LinuxCNC's INTERP_SUB_PARAMS).
constexpr int SUB_PARAMS = 30;

Interp &cur() { return *py_env().interp; }

// the interpreter must be there (it always is while it calls Python)
bool have_interp()
{
    if (py_env().interp) return true;
    PyErr_SetString(PyExc_RuntimeError, "no interpreter is running");
    return false;
}

// run f, turning an InterpError into a Python exception of type `type`
template <typename F>
bool guarded(PyObject *type, F f)
{
    try {
        f();
        return true;
    } catch (const InterpError &e) {
        PyErr_SetString(type, e.what());
        return false;
    }
}

// lower-case copy
std::string lower(std::string s)
{
    for (char &c : s) c = (char)tolower((unsigned char)c);
    return s;
}

// a sorted list of strings
PyObject *name_list(const std::set<std::string> &names)
{
    PyObject *l = PyList_New(0);
    for (const std::string &n : names) {
        PyRef s(PyUnicode_FromString(n.c_str()));
        if (l && s) PyList_Append(l, s.get());
    }
    return l;
}

PyObject *m_get(PyObject *, PyObject *arg)
{
    if (!have_interp()) return nullptr;
    return state_get(py_str(arg));
}

PyObject *m_set(PyObject *, PyObject *args)
{
    PyObject *name, *value;
    if (!PyArg_ParseTuple(args, "UO", &name, &value) || !have_interp()) return nullptr;
    if (!state_set(py_str(name), value)) return nullptr;
    Py_RETURN_NONE;
}

PyObject *m_names(PyObject *, PyObject *)
{
    return state_names();
}

// params[key]: numbered (int) or named (str) parameter
PyObject *m_param_get(PyObject *, PyObject *key)
{
    if (!have_interp()) return nullptr;
    double v = 0;
    if (PyLong_Check(key)) {
        long n = PyLong_AsLong(key);
        if (n < 1 || n >= PARAM_COUNT) {
            PyErr_Format(PyExc_IndexError, "parameter number %ld out of range", n);
            return nullptr;
        }
        return PyFloat_FromDouble(cur().get_numbered((int)n));
    }
    if (!PyUnicode_Check(key)) {
        PyErr_SetString(PyExc_TypeError, "parameter key must be an int or a str");
        return nullptr;
    }
    std::string name = lower(py_str(key));
    if (!guarded(PyExc_KeyError, [&] { v = cur().get_named(name); })) return nullptr;
    return PyFloat_FromDouble(v);
}

// params[key] = value
PyObject *m_param_set(PyObject *, PyObject *args)
{
    PyObject *key;
    double v;
    if (!PyArg_ParseTuple(args, "Od", &key, &v) || !have_interp()) return nullptr;
    Interp &in = cur();
    if (PyLong_Check(key)) {
        long n = PyLong_AsLong(key);
        if (!guarded(PyExc_IndexError, [&] { InterpAccess::set_numbered(in, (int)n, v); })) return nullptr;
        Py_RETURN_NONE;
    }
    std::string name = lower(py_str(key));
    if (name.empty()) {
        PyErr_SetString(PyExc_TypeError, "parameter key must be an int or a non-empty str");
        return nullptr;
    }
    if (!guarded(PyExc_KeyError, [&] { InterpAccess::set_named(in, name, v); })) return nullptr;
    Py_RETURN_NONE;
}

// every global name: predefined, namedparams, INI values read so far, globals, call level 0 locals
std::set<std::string> global_names(Interp &in)
{
    std::set<std::string> names;
    for (const std::string &n : InterpAccess::predefined_names()) names.insert(n);
    for (const std::string &n : InterpAccess::python_params(in)) names.insert(n);
    for (const auto &kv : InterpAccess::ini_cache(in)) names.insert(kv.first);
    for (const auto &kv : InterpAccess::globals(in)) names.insert(kv.first);
    for (const auto &kv : InterpAccess::frames(in)[0].locals) names.insert(kv.first);
    return names;
}

// params.locals() / params.globals()
PyObject *m_param_names(PyObject *, PyObject *arg)
{
    if (!have_interp()) return nullptr;
    Interp &in = cur();
    if (py_str(arg) == "globals") return name_list(global_names(in));
    std::set<std::string> names;
    for (const auto &kv : InterpAccess::frames(in).back().locals) names.insert(kv.first);
    return name_list(names);
}

PyObject *m_block_count(PyObject *, PyObject *)
{
    if (!have_interp()) return nullptr;
    return PyLong_FromSize_t(InterpAccess::remaps(cur()).size() + 1);
}

// blocks[level]: 0 the block being executed, n the block of remap level n
PyObject *m_block(PyObject *, PyObject *arg)
{
    if (!have_interp()) return nullptr;
    long level = PyLong_AsLong(arg);
    const auto &remaps = InterpAccess::remaps(cur());
    if ((level == -1 && PyErr_Occurred()) || level < 0 || level > (long)remaps.size()) {
        PyErr_SetString(PyExc_IndexError, "block index out of range");
        return nullptr;
    }
    if (level > 0) return block_dict(remaps[level - 1].block, remaps[level - 1].def);
    const Block *b = InterpAccess::current_block(cur());
    return block_dict(b ? *b : Block(), nullptr);
}

PyObject *m_context_count(PyObject *, PyObject *)
{
    if (!have_interp()) return nullptr;
    return PyLong_FromSize_t(InterpAccess::frames(cur()).size());
}

// named_params of a context: {name: (attr, value or None when computed on demand)}
PyObject *context_params(Interp &in, size_t level)
{
    PyObject *d = PyDict_New();
    auto add = [d](const std::string &name, int attr, PyObject *value) {
        PyRef v(value), t(Py_BuildValue("(iO)", attr, value ? value : Py_None));
        if (t) PyDict_SetItemString(d, name.c_str(), t.get());
    };
    for (const auto &kv : InterpAccess::frames(in)[level].locals) add(kv.first, 0, PyFloat_FromDouble(kv.second));
    if (level != 0) return d;
    for (const std::string &n : InterpAccess::predefined_names())
        add(n, PA_READONLY | PA_GLOBAL | PA_USE_LOOKUP, nullptr);
    for (const std::string &n : InterpAccess::python_params(in)) add(n, PA_READONLY | PA_GLOBAL | PA_PYTHON, nullptr);
    for (const auto &kv : InterpAccess::ini_cache(in))
        add(kv.first, PA_READONLY | PA_GLOBAL | PA_FROM_INI, PyFloat_FromDouble(kv.second));
    for (const auto &kv : InterpAccess::globals(in)) add(kv.first, PA_GLOBAL, PyFloat_FromDouble(kv.second));
    return d;
}

// sub_context[level]: the call level's procedure name, file, position, saved #1-#30, named parameters
PyObject *m_context(PyObject *, PyObject *arg)
{
    if (!have_interp()) return nullptr;
    Interp &in = cur();
    long level = PyLong_AsLong(arg);
    const auto &frames = InterpAccess::frames(in);
    if ((level == -1 && PyErr_Occurred()) || level < 0 || level >= (long)frames.size()) {
        PyErr_SetString(PyExc_IndexError, "context index out of range");
        return nullptr;
    }
    const CallFrame &f = frames[level];
    PyRef saved(PyTuple_New(SUB_PARAMS));
    for (int k = 0; saved && k < SUB_PARAMS; k++)
        PyTuple_SET_ITEM(saved.get(), k, PyFloat_FromDouble(f.saved_args[k + 1]));
    PyRef named(context_params(in, (size_t)level));
    return Py_BuildValue("{s:s,s:s,s:i,s:i,s:O,s:O,s:i}", "subname", f.sub_name.c_str(), "filename",
                         f.file ? f.file->path.c_str() : "", "sequence_number", f.return_line, "position",
                         (int)f.pos, "saved_params", saved.get(), "named_params", named.get(),
                         "call_type", f.python ? 1 : 0);
}

PyObject *m_tool_count(PyObject *, PyObject *)
{
    if (!have_interp()) return nullptr;
    return PyLong_FromSize_t(InterpAccess::state(cur()).tools.size());
}

// tool_table[index] as (toolno, pocketno, (x..w), diameter, frontangle, backangle, orientation)
PyObject *m_tool(PyObject *, PyObject *arg)
{
    if (!have_interp()) return nullptr;
    long k = PyLong_AsLong(arg);
    const auto &tools = InterpAccess::state(cur()).tools;
    if ((k == -1 && PyErr_Occurred()) || k < 0 || k >= (long)tools.size()) {
        PyErr_SetString(PyExc_IndexError, "tool table index out of range");
        return nullptr;
    }
    const CanonTool &t = tools[k];
    const CanonPose &o = t.offset;
    return Py_BuildValue("(ii(ddddddddd)dddi)", t.toolno, t.pocketno, o.x, o.y, o.z, o.a, o.b, o.c, o.u, o.v,
                         o.w, t.diameter, t.frontangle, t.backangle, t.orientation);
}

// the double field of a tool row that `name` names (offset axes as "x".."w"), nullptr if none
double *tool_double(CanonTool &t, const std::string &name)
{
    static const char axes[] = "xyzabcuvw";
    double *offs[] = {&t.offset.x, &t.offset.y, &t.offset.z, &t.offset.a, &t.offset.b, &t.offset.c,
                      &t.offset.u, &t.offset.v, &t.offset.w};
    if (name == "diameter") return &t.diameter;
    if (name == "frontangle") return &t.frontangle;
    if (name == "backangle") return &t.backangle;
    const char *axis = name.size() == 1 ? strchr(axes, name[0]) : nullptr;
    return axis ? offs[axis - axes] : nullptr;
}

// the int field of a tool row that `name` names, nullptr if none
int *tool_int(CanonTool &t, const std::string &name)
{
    if (name == "toolno") return &t.toolno;
    if (name == "pocketno") return &t.pocketno;
    if (name == "orientation") return &t.orientation;
    return nullptr;
}

// tool_table[index].field = value (offset fields as "x".."w")
PyObject *m_tool_set(PyObject *, PyObject *args)
{
    long k;
    const char *field;
    double v;
    if (!PyArg_ParseTuple(args, "lsd", &k, &field, &v) || !have_interp()) return nullptr;
    auto &tools = InterpAccess::state(cur()).tools;
    if (k < 0 || k >= (long)tools.size()) {
        PyErr_SetString(PyExc_IndexError, "tool table index out of range");
        return nullptr;
    }
    if (double *d = tool_double(tools[k], field)) {
        *d = v;
    } else if (int *i = tool_int(tools[k], field)) {
        *i = (int)v;
    } else {
        PyErr_Format(PyExc_AttributeError, "tool has no field '%s'", field);
        return nullptr;
    }
    Py_RETURN_NONE;
}

// execute(text) -> (LinuxCNC status code, error text)
PyObject *m_execute(PyObject *, PyObject *arg)
{
    if (!have_interp()) return nullptr;
    std::string text = py_str(arg);
    InterpStatus st = InterpAccess::execute(cur(), text);
    const std::string &err = st == INTERP_ERROR ? InterpAccess::error_text(cur()) : std::string();
    return Py_BuildValue("(is)", py_interp_code(st), err.c_str());
}

PyObject *m_set_errormsg(PyObject *, PyObject *arg)
{
    if (!have_interp()) return nullptr;
    InterpAccess::errormsg(cur()) = py_str(arg);
    Py_RETURN_NONE;
}

PyObject *m_get_errormsg(PyObject *, PyObject *)
{
    if (!have_interp()) return nullptr;
    return PyUnicode_FromString(InterpAccess::errormsg(cur()).c_str());
}

// set_speed(spindle, rpm): self.speed[spindle] = rpm
PyObject *m_set_speed(PyObject *, PyObject *args)
{
    int spindle;
    double rpm;
    if (!PyArg_ParseTuple(args, "id", &spindle, &rpm) || !have_interp()) return nullptr;
    if (spindle < 0 || spindle >= SPINDLE_COUNT) {
        PyErr_Format(PyExc_IndexError, "spindle %d out of range", spindle);
        return nullptr;
    }
    InterpAccess::state(cur()).speed[spindle] = rpm;
    Py_RETURN_NONE;
}

// set_tool_parameters(): the spindle row (tool_table[0], #5400-#5413) becomes the row of current_pocket
PyObject *m_set_tool_parameters(PyObject *, PyObject *)
{
    if (!have_interp()) return nullptr;
    InterpState &s = InterpAccess::state(cur());
    if (s.current_pocket > 0 && s.current_pocket < (int)s.tools.size())
        s.tools[0] = s.tools[s.current_pocket];
    else if (s.current_pocket == 0 && !s.tools.empty())
        s.tools[0] = CanonTool();
    return PyLong_FromLong(0);
}

// find_tool(toolno) -> tool-data index, -1 when absent
PyObject *m_find_tool(PyObject *, PyObject *arg)
{
    if (!have_interp()) return nullptr;
    long t = PyLong_AsLong(arg);
    if (t == -1 && PyErr_Occurred()) return nullptr;
    return PyLong_FromLong(InterpAccess::find_tool(cur(), (int)t));
}

// every REMAP definition: {code: dict}
PyObject *m_remaps(PyObject *, PyObject *)
{
    if (!have_interp()) return nullptr;
    Interp &in = cur();
    PyObject *d = PyDict_New();
    auto add = [d](const RemapDef &r) {
        PyRef v(remap_dict(r));
        std::string name;
        for (char c : r.code) name += (char)tolower((unsigned char)c);
        if (v) PyDict_SetItemString(d, name.c_str(), v.get());
    };
    for (const auto &kv : InterpAccess::g_remaps(in)) add(kv.second);
    for (const auto &kv : InterpAccess::m_remaps(in)) add(kv.second);
    for (const auto &kv : InterpAccess::letter_remaps(in)) add(kv.second);
    return d;
}

PyMethodDef METHODS[] = {
    {"get", m_get, METH_O, "value of an interpreter attribute"},
    {"set", m_set, METH_VARARGS, "set an interpreter attribute"},
    {"names", m_names, METH_NOARGS, "names of the interpreter attributes"},
    {"param_get", m_param_get, METH_O, "value of a numbered or named parameter"},
    {"param_set", m_param_set, METH_VARARGS, "set a numbered or named parameter"},
    {"param_names", m_param_names, METH_O, "'locals' or 'globals' parameter names"},
    {"block_count", m_block_count, METH_NOARGS, "remap level + 1"},
    {"block", m_block, METH_O, "the block of a remap level as a dict"},
    {"context_count", m_context_count, METH_NOARGS, "call level + 1"},
    {"context", m_context, METH_O, "a call level as a dict"},
    {"tool_count", m_tool_count, METH_NOARGS, "tool-table size"},
    {"tool", m_tool, METH_O, "one tool-table row"},
    {"tool_set", m_tool_set, METH_VARARGS, "change one field of a tool-table row"},
    {"execute", m_execute, METH_O, "run a line of G-code now"},
    {"set_errormsg", m_set_errormsg, METH_O, "the message of an INTERP_ERROR return"},
    {"get_errormsg", m_get_errormsg, METH_NOARGS, "the message set by set_errormsg"},
    {"find_tool", m_find_tool, METH_O, "tool-data index of a tool number"},
    {"set_speed", m_set_speed, METH_VARARGS, "set the speed of one spindle"},
    {"set_tool_parameters", m_set_tool_parameters, METH_NOARGS, "load tool_table[current_pocket] into the spindle"},
    {"remaps", m_remaps, METH_NOARGS, "the REMAP definitions"},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef MODULE = {PyModuleDef_HEAD_INIT, "_rs274ngc", "interpreter state for the interpreter module",
                      -1, METHODS, nullptr, nullptr, nullptr, nullptr};

} // namespace

// The private module `_rs274ngc`, new reference.
PyObject *make_state_module()
{
    return PyModule_Create(&MODULE);
}
