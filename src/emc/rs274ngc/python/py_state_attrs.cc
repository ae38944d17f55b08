// py_state_attrs.cc: the interpreter attributes Python sees on `self` (self.feed_rate, self.current_x, ...), as a table.
#include <cstring>

#include "interp_access.hh"
#include "py_plugin.hh"
#include "py_state.hh"

namespace {

const char AXES[] = "xyzabcuvw";
// LinuxCNC's cutter_comp_side values: 0 off, 1 left, 2 right.
constexpr int COMP_OFF = 0, COMP_LEFT = 1, COMP_RIGHT = 2;
// Spindle speeds Python sees (LinuxCNC's EMCMOT_MAX_SPINDLES).
constexpr int PY_SPINDLES = 8;

Interp &cur() { return *py_env().interp; }
InterpState &st() { return InterpAccess::state(cur()); }
PyObject *num(double v) { return PyFloat_FromDouble(v); }
PyObject *integer(long v) { return PyLong_FromLong(v); }

// a Python number as double; false with a Python error set
bool to_double(PyObject *o, double &v)
{
    v = PyFloat_AsDouble(o);
    return !(v == -1.0 && PyErr_Occurred());
}

// a Python number as int; false with a Python error set
bool to_int(PyObject *o, int &v)
{
    long l = PyLong_AsLong(o);
    if (l == -1 && PyErr_Occurred()) return false;
    v = (int)l;
    return true;
}

// a tuple of ints
PyObject *int_tuple(const int *v, int n)
{
    PyObject *t = PyTuple_New(n);
    for (int k = 0; t && k < n; k++) PyTuple_SET_ITEM(t, k, PyLong_FromLong(v[k]));
    return t;
}

// the queue-buster flags all set one request: end the block with execute-finish
bool set_finish(PyObject *o)
{
    int on = PyObject_IsTrue(o);
    if (on < 0) return false;
    InterpAccess::finish_request(cur()) = on != 0;
    return true;
}

int comp_side()
{
    CanonSide s = st().comp_side;
    return s == CANON_SIDE_LEFT ? COMP_LEFT : s == CANON_SIDE_RIGHT ? COMP_RIGHT : COMP_OFF;
}

// One attribute: getter and (when writable) setter.
struct StateAttr {
    const char *name;
    PyObject *(*get)();
    bool (*set)(PyObject *value);
};

const StateAttr ATTRS[] = {
    {"call_level", [] { return integer((long)InterpAccess::frames(cur()).size() - 1); }, nullptr},
    {"remap_level", [] { return integer((long)InterpAccess::remaps(cur()).size()); }, nullptr},
    {"return_value", [] { return num(InterpAccess::return_value(cur())); },
     [](PyObject *o) { return to_double(o, InterpAccess::return_value(cur())); }},
    {"value_returned", [] { return integer((long)InterpAccess::value_returned(cur())); },
     [](PyObject *o) { return to_double(o, InterpAccess::value_returned(cur())); }},
    {"task", [] { return integer(InterpAccess::task(cur()) ? 1 : 0); }, nullptr},
    {"debugmask", [] { return integer(py_env().debugmask); }, nullptr},
    {"loggingLevel", [] { return integer(py_env().logging_level); }, nullptr},
    {"feed_rate", [] { return num(st().feed_rate); }, [](PyObject *o) { return to_double(o, st().feed_rate); }},
    {"speed", [] {
         PyObject *l = PyList_New(PY_SPINDLES);
         for (int k = 0; l && k < PY_SPINDLES; k++)
             PyList_SET_ITEM(l, k, PyFloat_FromDouble(k < SPINDLE_COUNT ? st().speed[k] : 0.0));
         return l; }, nullptr},
    {"active_spindle", [] { return integer(0); }, nullptr},
    {"selected_tool", [] { return integer(st().selected_tool); },
     [](PyObject *o) { return to_int(o, st().selected_tool); }},
    {"selected_pocket", [] { return integer(st().selected_pocket); },
     [](PyObject *o) { return to_int(o, st().selected_pocket); }},
    {"current_pocket", [] { return integer(st().current_pocket); },
     [](PyObject *o) { return to_int(o, st().current_pocket); }},
    {"current_tool", [] { return integer(st().tools.empty() || st().tools[0].toolno < 0 ? 0 : st().tools[0].toolno); },
     [](PyObject *o) { return !st().tools.empty() && to_int(o, st().tools[0].toolno); }},
    {"cutter_comp_side", [] { return integer(comp_side()); }, nullptr},
    {"cutter_comp_radius", [] { return num(st().comp_radius); }, nullptr},
    {"cutter_comp_orientation", [] { return integer(st().comp_orientation); }, nullptr},
    {"motion_mode", [] { return integer(st().motion_mode); }, [](PyObject *o) { return to_int(o, st().motion_mode); }},
    {"plane", [] { return integer(st().plane); }, nullptr},
    {"distance_mode", [] { return integer(st().distance_incremental ? 1 : 0); }, nullptr},
    {"ijk_distance_mode", [] { return integer(st().ijk_absolute ? 0 : 1); }, nullptr},
    {"feed_mode", [] { return integer(st().feed_mode); }, nullptr},
    {"length_units", [] { return integer(st().units); }, nullptr},
    {"origin_index", [] { return integer(st().origin_index); }, nullptr},
    {"rotation_xy", [] { return num(st().rotation_xy); }, nullptr},
    {"retract_mode", [] { return integer(st().retract); }, nullptr},
    {"sequence_number", [] { return integer(st().sequence_number); }, nullptr},
    {"filename", [] { return PyUnicode_FromString(st().filename.c_str()); }, nullptr},
    {"linetext", [] { return PyUnicode_FromString(st().line_text.c_str()); }, nullptr},
    {"mist", [] { return integer(st().mist); }, nullptr},
    {"flood", [] { return integer(st().flood); }, nullptr},
    {"speed_override", [] { return integer(st().speed_override); }, nullptr},
    {"feed_override", [] { return integer(st().feed_override); }, nullptr},
    {"adaptive_feed", [] { return integer(st().adaptive_feed); }, nullptr},
    {"feed_hold", [] { return integer(st().feed_hold); }, nullptr},
    {"toolchange_flag", [] { return integer(InterpAccess::finish_request(cur())); }, set_finish},
    {"tool_change_flag", [] { return integer(InterpAccess::finish_request(cur())); }, set_finish},
    {"input_flag", [] { return integer(InterpAccess::finish_request(cur())); }, set_finish},
    {"probe_flag", [] { return integer(InterpAccess::finish_request(cur())); }, set_finish},
    {"random_toolchanger", [] { return integer(st().settings.random_toolchanger); }, nullptr},
    {"tool_change_at_g30", [] { return integer(st().settings.tool_change_at_g30); }, nullptr},
    {"tool_change_quill_up", [] { return integer(st().settings.tool_change_quill_up); }, nullptr},
    {"tool_change_with_spindle_on", [] { return integer(st().settings.tool_change_with_spindle_on); }, nullptr},
    {"active_g_codes", [] { int g[17]; cur().active_g_codes(g); return int_tuple(g, 17); }, nullptr},
    {"active_m_codes", [] { int m[10]; cur().active_m_codes(m); return int_tuple(m, 10); }, nullptr},
    {"active_settings", [] {
         double v[5];
         cur().active_settings(v);
         return Py_BuildValue("(ddddd)", v[0], v[1], v[2], v[3], v[4]); }, nullptr},
    {nullptr, nullptr, nullptr},
};

// "<prefix><axis>" names a pose member: current_x, origin_offset_y, axis_offset_z, tool_offset_a, ...
double *pose_member(const std::string &name, bool &writable)
{
    static const struct { const char *prefix; Pose InterpState::*pose; bool writable; } poses[] = {
        {"current_", &InterpState::current, true},
        {"origin_offset_", &InterpState::origin_offset, false},
        {"axis_offset_", &InterpState::axis_offset, false},
        {"tool_offset_", &InterpState::tool_offset, false},
    };
    for (const auto &p : poses) {
        size_t n = strlen(p.prefix);
        if (name.size() != n + 1 || name.compare(0, n, p.prefix) != 0) continue;
        const char *axis = strchr(AXES, name[n]);
        if (!axis || !name[n]) return nullptr;
        writable = p.writable;
        return &(st().*p.pose)[axis - AXES];
    }
    return nullptr;
}

} // namespace

// Value of interpreter attribute `name`; nullptr with AttributeError when there is none.
PyObject *state_get(const std::string &name)
{
    bool writable = false;
    if (double *v = pose_member(name, writable)) return PyFloat_FromDouble(*v);
    for (const StateAttr *a = ATTRS; a->name; a++)
        if (name == a->name) return a->get();
    PyErr_Format(PyExc_AttributeError, "interpreter has no attribute '%s'", name.c_str());
    return nullptr;
}

// Set interpreter attribute `name`; false with a Python error set.
bool state_set(const std::string &name, PyObject *value)
{
    bool writable = false;
    double *v = pose_member(name, writable);
    if (v && writable) return to_double(value, *v);
    for (const StateAttr *a = ATTRS; !v && a->name; a++) {
        if (name != a->name) continue;
        if (a->set) return a->set(value);
        break;
    }
    PyErr_Format(PyExc_AttributeError, "interpreter attribute '%s' is read-only", name.c_str());
    return false;
}

// Names of all interpreter attributes (for dir()).
PyObject *state_names()
{
    PyObject *l = PyList_New(0);
    for (const StateAttr *a = ATTRS; l && a->name; a++) {
        PyRef s(PyUnicode_FromString(a->name));
        PyList_Append(l, s.get());
    }
    for (const char *prefix : {"current_", "origin_offset_", "axis_offset_", "tool_offset_"})
        for (const char *axis = AXES; l && *axis; axis++) {
            PyRef s(PyUnicode_FromFormat("%s%c", prefix, *axis));
            PyList_Append(l, s.get());
        }
    return l;
}
