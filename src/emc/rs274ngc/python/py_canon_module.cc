// py_canon_module.cc: the `emccanon` module: LinuxCNC's canon calls (STRAIGHT_FEED, MESSAGE, ...) for Python,
// sent to the interpreter's canon in order with everything else it emits.
#include <vector>

#include "interp_access.hh"
#include "py_plugin.hh"

namespace {

Canon &canon() { return InterpAccess::canon(*py_env().interp); }

// run a canon call, turning an interpreter error (cutter compensation) into RuntimeError
template <typename F>
PyObject *call(F f)
{
    if (!py_env().interp) {
        PyErr_SetString(PyExc_RuntimeError, "no interpreter is running");
        return nullptr;
    }
    try {
        f();
    } catch (const InterpError &e) {
        PyErr_SetString(PyExc_RuntimeError, e.what());
        return nullptr;
    }
    Py_RETURN_NONE;
}

// Argument shapes the table-driven calls take.
enum CanonSig { SIG_VOID, SIG_INT, SIG_DOUBLE, SIG_TEXT, SIG_LINE_POSE, SIG_POSE, SIG_INT_DOUBLE };

// One canon call of a common shape.
struct CanonCall {
    const char *name;
    CanonSig sig;
    void (Canon::*fn_void)();
    void (Canon::*fn_int)(int);
    void (Canon::*fn_double)(double);
    void (Canon::*fn_text)(const std::string &);
    void (Canon::*fn_line_pose)(int, const CanonPose &);
    void (Canon::*fn_pose)(const CanonPose &);
    void (Canon::*fn_int_double)(int, double);
};

// table rows, one constructor per shape
CanonCall v(const char *n, void (Canon::*f)()) { return {n, SIG_VOID, f, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr}; }
CanonCall i(const char *n, void (Canon::*f)(int)) { return {n, SIG_INT, nullptr, f, nullptr, nullptr, nullptr, nullptr, nullptr}; }
CanonCall d(const char *n, void (Canon::*f)(double)) { return {n, SIG_DOUBLE, nullptr, nullptr, f, nullptr, nullptr, nullptr, nullptr}; }
CanonCall t(const char *n, void (Canon::*f)(const std::string &)) { return {n, SIG_TEXT, nullptr, nullptr, nullptr, f, nullptr, nullptr, nullptr}; }
CanonCall lp(const char *n, void (Canon::*f)(int, const CanonPose &)) { return {n, SIG_LINE_POSE, nullptr, nullptr, nullptr, nullptr, f, nullptr, nullptr}; }
CanonCall p(const char *n, void (Canon::*f)(const CanonPose &)) { return {n, SIG_POSE, nullptr, nullptr, nullptr, nullptr, nullptr, f, nullptr}; }
CanonCall id(const char *n, void (Canon::*f)(int, double)) { return {n, SIG_INT_DOUBLE, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, f}; }

const std::vector<CanonCall> &calls()
{
    static const std::vector<CanonCall> table = {
        v("TURN_PROBE_ON", &Canon::turn_probe_on), v("TURN_PROBE_OFF", &Canon::turn_probe_off),
        v("STOP_SPEED_FEED_SYNCH", &Canon::stop_speed_feed_synch), v("MIST_ON", &Canon::mist_on),
        v("MIST_OFF", &Canon::mist_off), v("FLOOD_ON", &Canon::flood_on), v("FLOOD_OFF", &Canon::flood_off),
        v("RELOAD_TOOLDATA", &Canon::reload_tooldata),
        v("ENABLE_FEED_OVERRIDE", &Canon::enable_feed_override),
        v("DISABLE_FEED_OVERRIDE", &Canon::disable_feed_override),
        v("ENABLE_ADAPTIVE_FEED", &Canon::enable_adaptive_feed),
        v("DISABLE_ADAPTIVE_FEED", &Canon::disable_adaptive_feed),
        v("ENABLE_FEED_HOLD", &Canon::enable_feed_hold), v("DISABLE_FEED_HOLD", &Canon::disable_feed_hold),
        v("PROGRAM_STOP", &Canon::program_stop), v("OPTIONAL_PROGRAM_STOP", &Canon::optional_program_stop),
        v("PALLET_SHUTTLE", &Canon::pallet_shuttle), v("PROGRAM_END", &Canon::program_end),
        v("FINISH", &Canon::finish), v("LOGCLOSE", &Canon::logclose), v("ON_RESET", &Canon::on_reset),
        i("SELECT_TOOL", &Canon::select_tool), i("CHANGE_TOOL_NUMBER", &Canon::change_tool_number),
        i("STOP_SPINDLE_TURNING", &Canon::stop_spindle_turning),
        i("ENABLE_SPEED_OVERRIDE", &Canon::enable_speed_override),
        i("DISABLE_SPEED_OVERRIDE", &Canon::disable_speed_override),
        i("SET_MOTION_OUTPUT_BIT", &Canon::set_motion_output_bit),
        i("CLEAR_MOTION_OUTPUT_BIT", &Canon::clear_motion_output_bit),
        i("SET_AUX_OUTPUT_BIT", &Canon::set_aux_output_bit),
        i("CLEAR_AUX_OUTPUT_BIT", &Canon::clear_aux_output_bit),
        d("SET_FEED_RATE", &Canon::set_feed_rate), d("SET_TRAVERSE_RATE", &Canon::set_traverse_rate),
        d("DWELL", &Canon::dwell), d("SET_XY_ROTATION", &Canon::set_xy_rotation),
        d("SET_NAIVECAM_TOLERANCE", &Canon::set_naivecam_tolerance),
        t("COMMENT", &Canon::comment), t("MESSAGE", &Canon::message), t("LOG", &Canon::log),
        t("LOGOPEN", &Canon::logopen), t("LOGAPPEND", &Canon::logappend),
        lp("STRAIGHT_TRAVERSE", &Canon::straight_traverse), lp("STRAIGHT_FEED", &Canon::straight_feed),
        p("SET_G92_OFFSET", &Canon::set_g92_offset), p("USE_TOOL_LENGTH_OFFSET", &Canon::use_tool_length_offset),
        id("SET_SPINDLE_SPEED", &Canon::set_spindle_speed), id("SET_SPINDLE_MODE", &Canon::set_spindle_mode),
        id("SET_MOTION_OUTPUT_VALUE", &Canon::set_motion_output_value),
        id("SET_AUX_OUTPUT_VALUE", &Canon::set_aux_output_value),
        id("WAIT_SPINDLE_ORIENT_COMPLETE", &Canon::wait_spindle_orient_complete),
    };
    return table;
}

// parse 9 axis values starting at tuple index first (missing trailing ones are 0)
bool parse_pose(PyObject *args, Py_ssize_t first, CanonPose &pose)
{
    double *f[] = {&pose.x, &pose.y, &pose.z, &pose.a, &pose.b, &pose.c, &pose.u, &pose.v, &pose.w};
    Py_ssize_t n = PyTuple_GET_SIZE(args) - first;
    if (n < 3 || n > 9) {
        PyErr_SetString(PyExc_TypeError, "expected 3 to 9 axis values (x y z [a b c u v w])");
        return false;
    }
    for (Py_ssize_t k = 0; k < n; k++) {
        *f[k] = PyFloat_AsDouble(PyTuple_GET_ITEM(args, first + k));
        if (*f[k] == -1.0 && PyErr_Occurred()) return false;
    }
    return true;
}

// the dispatcher of every table-driven call (self = its index in the table)
PyObject *dispatch(PyObject *self, PyObject *args)
{
    const CanonCall &c = calls()[PyLong_AsSize_t(self)];
    int n = 0;
    double x = 0;
    const char *s = nullptr;
    CanonPose pose;
    switch (c.sig) {
    case SIG_VOID:
        if (!PyArg_ParseTuple(args, "")) return nullptr;
        return call([&] { (canon().*c.fn_void)(); });
    case SIG_INT:
        if (!PyArg_ParseTuple(args, "i", &n)) return nullptr;
        return call([&] { (canon().*c.fn_int)(n); });
    case SIG_DOUBLE:
        if (!PyArg_ParseTuple(args, "d", &x)) return nullptr;
        return call([&] { (canon().*c.fn_double)(x); });
    case SIG_TEXT:
        if (!PyArg_ParseTuple(args, "s", &s)) return nullptr;
        return call([&] { (canon().*c.fn_text)(s); });
    case SIG_LINE_POSE:
        if (PyTuple_GET_SIZE(args) < 1 || (n = (int)PyLong_AsLong(PyTuple_GET_ITEM(args, 0)), PyErr_Occurred()) ||
            !parse_pose(args, 1, pose))
            return nullptr;
        return call([&] { (canon().*c.fn_line_pose)(n, pose); });
    case SIG_POSE:
        if (!parse_pose(args, 0, pose)) return nullptr;
        return call([&] { (canon().*c.fn_pose)(pose); });
    case SIG_INT_DOUBLE:
        if (!PyArg_ParseTuple(args, "id", &n, &x)) return nullptr;
        return call([&] { (canon().*c.fn_int_double)(n, x); });
    }
    Py_RETURN_NONE;
}

PyObject *arc_feed(PyObject *, PyObject *args)
{
    int line, rot;
    double e1, e2, a1, a2, ae, a = 0, b = 0, c = 0, u = 0, v = 0, w = 0;
    if (!PyArg_ParseTuple(args, "iddddid|dddddd", &line, &e1, &e2, &a1, &a2, &rot, &ae, &a, &b, &c, &u, &v, &w))
        return nullptr;
    return call([&] { canon().arc_feed(line, e1, e2, a1, a2, rot, ae, a, b, c, u, v, w); });
}

PyObject *straight_probe(PyObject *, PyObject *args)
{
    CanonPose pose;
    Py_ssize_t n = PyTuple_GET_SIZE(args);
    if (n < 5) {
        PyErr_SetString(PyExc_TypeError, "STRAIGHT_PROBE(line, x, y, z, ..., probe_type)");
        return nullptr;
    }
    int line = (int)PyLong_AsLong(PyTuple_GET_ITEM(args, 0));
    int type = (int)PyLong_AsLong(PyTuple_GET_ITEM(args, n - 1));
    PyRef mid(PyTuple_GetSlice(args, 0, n - 1));
    if (PyErr_Occurred() || !parse_pose(mid.get(), 1, pose)) return nullptr;
    return call([&] { canon().straight_probe(line, pose, type); });
}

PyObject *rigid_tap(PyObject *, PyObject *args)
{
    int line;
    double x, y, z, scale = 1.0;
    if (!PyArg_ParseTuple(args, "iddd|d", &line, &x, &y, &z, &scale)) return nullptr;
    return call([&] { canon().rigid_tap(line, x, y, z, scale); });
}

// START_SPINDLE_CLOCKWISE / _COUNTERCLOCKWISE(spindle[, wait_for_at_speed]): the wait flag is task's
PyObject *spindle_start(PyObject *self, PyObject *args)
{
    int spindle, wait = 1;
    if (!PyArg_ParseTuple(args, "i|i", &spindle, &wait)) return nullptr;
    bool ccw = py_str(self) == "START_SPINDLE_COUNTERCLOCKWISE";
    return call([&] {
        if (ccw) canon().start_spindle_counterclockwise(spindle);
        else canon().start_spindle_clockwise(spindle);
    });
}

// CANON_ERROR(text): an operator error, sent at once (not held behind cutter-compensation moves)
PyObject *canon_error(PyObject *, PyObject *args)
{
    const char *text;
    if (!PyArg_ParseTuple(args, "s", &text)) return nullptr;
    return call([&] { InterpAccess::real_canon(*py_env().interp).canon_error(text); });
}

PyObject *change_tool(PyObject *, PyObject *args)
{
    int slot = 0;
    if (!PyArg_ParseTuple(args, "|i", &slot)) return nullptr;
    return call([&] { canon().change_tool(); });
}

PyObject *set_g5x_offset(PyObject *, PyObject *args)
{
    CanonPose pose;
    if (PyTuple_GET_SIZE(args) < 1) return PyErr_Format(PyExc_TypeError, "SET_G5X_OFFSET(origin, x, y, z, ...)");
    int origin = (int)PyLong_AsLong(PyTuple_GET_ITEM(args, 0));
    if (PyErr_Occurred() || !parse_pose(args, 1, pose)) return nullptr;
    return call([&] { canon().set_g5x_offset(origin, pose); });
}

PyObject *start_speed_feed_synch(PyObject *, PyObject *args)
{
    int spindle, velocity_mode;
    double feed_per_rev;
    if (!PyArg_ParseTuple(args, "idp", &spindle, &feed_per_rev, &velocity_mode)) return nullptr;
    return call([&] { canon().start_speed_feed_synch(spindle, feed_per_rev, velocity_mode != 0); });
}

PyObject *set_motion_control_mode(PyObject *, PyObject *args)
{
    int mode;
    double tol = 0;
    if (!PyArg_ParseTuple(args, "i|d", &mode, &tol)) return nullptr;
    return call([&] { canon().set_motion_control_mode((CanonMotionMode)mode, tol); });
}

PyObject *orient_spindle(PyObject *, PyObject *args)
{
    int spindle, mode = 0;
    double angle;
    if (!PyArg_ParseTuple(args, "id|i", &spindle, &angle, &mode)) return nullptr;
    return call([&] { canon().orient_spindle(spindle, angle, mode); });
}

PyObject *select_plane(PyObject *, PyObject *args)
{
    int plane;
    if (!PyArg_ParseTuple(args, "i", &plane)) return nullptr;
    return call([&] { canon().select_plane((CanonPlane)plane); });
}

PyObject *use_length_units(PyObject *, PyObject *args)
{
    int units;
    if (!PyArg_ParseTuple(args, "i", &units)) return nullptr;
    return call([&] { canon().use_length_units((CanonUnits)units); });
}

PyObject *set_feed_mode(PyObject *, PyObject *args)
{
    int spindle, mode;
    if (!PyArg_ParseTuple(args, "ii", &spindle, &mode)) return nullptr;
    return call([&] { canon().set_feed_mode(spindle, mode); });
}

PyObject *set_tool_table_entry(PyObject *, PyObject *args)
{
    int index;
    CanonTool t;
    CanonPose &o = t.offset;
    if (!PyArg_ParseTuple(args, "iiddddddddddddi", &index, &t.toolno, &o.x, &o.y, &o.z, &o.a, &o.b, &o.c, &o.u,
                          &o.v, &o.w, &t.diameter, &t.frontangle, &t.backangle, &t.orientation))
        return nullptr;
    return call([&] { canon().set_tool_table_entry(index, t); });
}

PyObject *wait_input(PyObject *, PyObject *args)
{
    int index, type, wait_type, result = 0;
    double timeout;
    if (!PyArg_ParseTuple(args, "iiid", &index, &type, &wait_type, &timeout)) return nullptr;
    PyRef r(call([&] { result = canon().wait_input(index, type, wait_type, timeout); }));
    return r ? PyLong_FromLong(result) : nullptr;
}

// a CanonPose as a 9-tuple
PyObject *pose_tuple(const CanonPose &p)
{
    return Py_BuildValue("(ddddddddd)", p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w);
}

PyObject *get_position(PyObject *, PyObject *)
{
    return py_env().interp ? pose_tuple(canon().get_external_position()) : call([] {});
}

PyObject *get_probe_position(PyObject *, PyObject *)
{
    return py_env().interp ? pose_tuple(canon().get_external_probe_position()) : call([] {});
}

// GET_EXTERNAL_* queries returning one number
PyObject *query(PyObject *self, PyObject *args)
{
    if (!py_env().interp) return call([] {});
    std::string name = py_str(self);
    int index = 0, def = 0;
    Canon &c = canon();
    if (name == "GET_EXTERNAL_DIGITAL_INPUT" || name == "GET_EXTERNAL_ANALOG_INPUT") {
        double fallback = 0;
        if (!PyArg_ParseTuple(args, "i|d", &index, &fallback)) return nullptr;
        def = (int)fallback;
        if (name == "GET_EXTERNAL_DIGITAL_INPUT") return PyLong_FromLong(c.get_external_digital_input(index, def));
        return PyFloat_FromDouble(c.get_external_analog_input(index, fallback));
    }
    if (name == "GET_EXTERNAL_PROBE_TRIPPED_VALUE") return PyFloat_FromDouble(c.get_external_probe_tripped_value());
    if (name == "GET_EXTERNAL_LENGTH_UNITS") return PyFloat_FromDouble(c.get_external_length_units());
    if (name == "GET_EXTERNAL_LENGTH_UNIT_TYPE") return PyLong_FromLong(c.get_external_length_unit_type());
    if (name == "GET_EXTERNAL_MOTION_CONTROL_MODE") return PyLong_FromLong(c.get_external_motion_control_mode());
    if (name == "GET_EXTERNAL_MOTION_CONTROL_TOLERANCE")
        return PyFloat_FromDouble(c.get_external_motion_control_tolerance());
    if (name == "GET_EXTERNAL_TOOL_SLOT") return PyLong_FromLong(c.get_external_tool_slot());
    if (name == "GET_EXTERNAL_SELECTED_TOOL_SLOT") return PyLong_FromLong(c.get_external_selected_tool_slot());
    if (name == "GET_EXTERNAL_QUEUE_EMPTY") return PyLong_FromLong(c.get_external_queue_empty());
    if (name == "GET_EXTERNAL_FEED_HOLD_ENABLE") return PyLong_FromLong(c.get_external_feed_hold_enable());
    if (name == "GET_EXTERNAL_ADAPTIVE_FEED_ENABLE") return PyLong_FromLong(c.get_external_adaptive_feed_enable());
    if (name == "GET_EXTERNAL_TOOLCHANGER_FAULT") return PyLong_FromLong(c.get_external_toolchanger_fault());
    return PyLong_FromLong(c.get_external_toolchanger_reason());
}

// functions dispatched by name (self is the name)
const struct { const char *name; PyCFunction fn; } BY_NAME[] = {
    {"START_SPINDLE_CLOCKWISE", spindle_start},
    {"START_SPINDLE_COUNTERCLOCKWISE", spindle_start},
};

const char *const QUERIES[] = {
    "GET_EXTERNAL_DIGITAL_INPUT", "GET_EXTERNAL_ANALOG_INPUT", "GET_EXTERNAL_PROBE_TRIPPED_VALUE",
    "GET_EXTERNAL_LENGTH_UNITS", "GET_EXTERNAL_LENGTH_UNIT_TYPE", "GET_EXTERNAL_MOTION_CONTROL_MODE",
    "GET_EXTERNAL_MOTION_CONTROL_TOLERANCE", "GET_EXTERNAL_TOOL_SLOT", "GET_EXTERNAL_SELECTED_TOOL_SLOT",
    "GET_EXTERNAL_QUEUE_EMPTY", "GET_EXTERNAL_FEED_HOLD_ENABLE", "GET_EXTERNAL_ADAPTIVE_FEED_ENABLE",
    "GET_EXTERNAL_TOOLCHANGER_FAULT", "GET_EXTERNAL_TOOLCHANGER_REASON", nullptr,
};

PyMethodDef SPECIAL[] = {
    {"ARC_FEED", arc_feed, METH_VARARGS, nullptr},
    {"STRAIGHT_PROBE", straight_probe, METH_VARARGS, nullptr},
    {"RIGID_TAP", rigid_tap, METH_VARARGS, nullptr},
    {"CHANGE_TOOL", change_tool, METH_VARARGS, nullptr},
    {"CANON_ERROR", canon_error, METH_VARARGS, nullptr},
    {"SET_G5X_OFFSET", set_g5x_offset, METH_VARARGS, nullptr},
    {"START_SPEED_FEED_SYNCH", start_speed_feed_synch, METH_VARARGS, nullptr},
    {"SET_MOTION_CONTROL_MODE", set_motion_control_mode, METH_VARARGS, nullptr},
    {"ORIENT_SPINDLE", orient_spindle, METH_VARARGS, nullptr},
    {"SELECT_PLANE", select_plane, METH_VARARGS, nullptr},
    {"USE_LENGTH_UNITS", use_length_units, METH_VARARGS, nullptr},
    {"SET_FEED_MODE", set_feed_mode, METH_VARARGS, nullptr},
    {"SET_TOOL_TABLE_ENTRY", set_tool_table_entry, METH_VARARGS, nullptr},
    {"WAIT", wait_input, METH_VARARGS, nullptr},
    {"GET_EXTERNAL_POSITION", get_position, METH_NOARGS, nullptr},
    {"GET_EXTERNAL_PROBE_POSITION", get_probe_position, METH_NOARGS, nullptr},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef MODULE = {PyModuleDef_HEAD_INIT, "emccanon", "canon calls of the running interpreter", -1, SPECIAL,
                      nullptr, nullptr, nullptr, nullptr};

// add function `name` to module m, dispatched by fn with `self` as its data
bool add_function(PyObject *m, PyMethodDef *def, PyObject *self)
{
    PyRef f(PyCFunction_NewEx(def, self, nullptr));
    return f && PyModule_AddObjectRef(m, def->ml_name, f.get()) == 0;
}

} // namespace

// The `emccanon` module, new reference.
PyObject *make_canon_module()
{
    PyRef m(PyModule_Create(&MODULE));
    if (!m) return nullptr;
    static std::vector<PyMethodDef> defs;   // functions keep pointers to their definitions: built once
    if (defs.empty()) {
        for (const CanonCall &c : calls()) defs.push_back({c.name, dispatch, METH_VARARGS, nullptr});
        for (const char *const *q = QUERIES; *q; q++) defs.push_back({*q, query, METH_VARARGS, nullptr});
        for (const auto &b : BY_NAME) defs.push_back({b.name, b.fn, METH_VARARGS, nullptr});
    }
    for (size_t k = 0; k < calls().size(); k++) {
        PyRef index(PyLong_FromSize_t(k));
        if (!add_function(m.get(), &defs[k], index.get())) return nullptr;
    }
    for (size_t k = calls().size(); k < defs.size(); k++) {
        PyRef name(PyUnicode_FromString(defs[k].ml_name));
        if (!add_function(m.get(), &defs[k], name.get())) return nullptr;
    }
    return m.release();
}
