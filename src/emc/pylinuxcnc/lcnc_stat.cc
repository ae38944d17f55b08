// lcnc_stat.cc: linuxcnc.stat: poll() copies emcStatus; scalar attributes come from one table.
#include "lcnc_py.hh"

#include <cstring>
#include <vector>

PyTypeObject *lcnc_stat_type = nullptr;

namespace {

// One scalar attribute: its name, how to read it from the status copy, its doc.
struct StatAttr {
    const char *name;
    PyObject *(*get)(const EMC_STAT &s);
    const char *doc;
};

#define INT_ATTR(name, expr, doc) \
    {name, [](const EMC_STAT &s) -> PyObject * { return PyLong_FromLongLong(static_cast<long long>(expr)); }, doc}
#define UINT_ATTR(name, expr, doc) \
    {name, [](const EMC_STAT &s) -> PyObject * { return PyLong_FromUnsignedLongLong(expr); }, doc}
#define BOOL_ATTR(name, expr, doc) \
    {name, [](const EMC_STAT &s) -> PyObject * { return PyBool_FromLong((expr) != 0); }, doc}
#define FLOAT_ATTR(name, expr, doc) \
    {name, [](const EMC_STAT &s) -> PyObject * { return PyFloat_FromDouble(expr); }, doc}
#define TEXT_ATTR(name, field, doc) \
    {name, [](const EMC_STAT &s) -> PyObject * { return lcnc_text(s.field, sizeof s.field); }, doc}

const StatAttr stat_attrs[] = {
    INT_ATTR("echo_serial_number", s.echo_serial_number, "serial of the last command task read"),
    INT_ATTR("state", s.status, "RCS_DONE, RCS_EXEC or RCS_ERROR"),
    INT_ATTR("task_mode", s.task.mode, "MODE_MANUAL, MODE_AUTO or MODE_MDI"),
    INT_ATTR("task_state", s.task.state, "STATE_ESTOP, STATE_ESTOP_RESET or STATE_ON"),
    INT_ATTR("exec_state", s.task.execState, "EXEC_*"),
    INT_ATTR("interp_state", s.task.interpState, "INTERP_*"),
    INT_ATTR("call_level", s.task.callLevel, "subroutine depth"),
    INT_ATTR("read_line", s.task.readLine, "line the interpreter read last"),
    INT_ATTR("motion_line", s.task.motionLine, "source line motion executes"),
    INT_ATTR("current_line", s.task.currentLine, "source line task issued last"),
    TEXT_ATTR("file", task.file, "program file as given to program_open"),
    TEXT_ATTR("command", task.command, "MDI text being executed"),
    TEXT_ATTR("ini_filename", task.ini_filename, "INI file of the running configuration"),
    INT_ATTR("program_units", s.task.programUnits, "1 inch, 2 mm, 3 cm"),
    INT_ATTR("interpreter_errcode", s.task.interpreter_errcode, "last interpreter return code"),
    BOOL_ATTR("optional_stop", s.task.optional_stop_state, "optional stop (M1) enabled"),
    BOOL_ATTR("block_delete", s.task.block_delete_state, "block delete enabled"),
    BOOL_ATTR("input_timeout", s.task.input_timeout, "M66 wait timed out"),
    INT_ATTR("task_paused", s.task.task_paused, "task paused flag"),
    FLOAT_ATTR("rotation_xy", s.task.rotation_xy, "XY rotation (G10 L2 R), degrees"),
    FLOAT_ATTR("delay_left", s.task.delayLeft, "remaining dwell, s"),
    INT_ATTR("queued_mdi_commands", s.task.queuedMDIcommands, "MDI commands waiting"),
    UINT_ATTR("taskbeat", s.task.taskbeat, "task cycles"),
    FLOAT_ATTR("linear_units", s.motion.traj.linearUnits, "machine units per mm"),
    FLOAT_ATTR("angular_units", s.motion.traj.angularUnits, "machine units per degree"),
    FLOAT_ATTR("cycle_time", s.motion.traj.cycleTime, "servo period, s"),
    INT_ATTR("joints", s.motion.traj.joints, "number of joints"),
    INT_ATTR("spindles", s.motion.traj.spindles, "number of spindles"),
    INT_ATTR("axis_mask", s.motion.traj.axis_mask, "X=1 Y=2 Z=4 A=8 B=16 C=32 U=64 V=128 W=256"),
    INT_ATTR("motion_mode", s.motion.traj.mode, "TRAJ_MODE_FREE, _COORD or _TELEOP"),
    BOOL_ATTR("enabled", s.motion.traj.enabled, "motion enabled (machine on)"),
    BOOL_ATTR("inpos", s.motion.traj.inpos, "machine in position"),
    INT_ATTR("queue", s.motion.traj.queue, "segments in the planner queue"),
    INT_ATTR("active_queue", s.motion.traj.activeQueue, "segments being blended"),
    BOOL_ATTR("queue_full", s.motion.traj.queueFull, "planner queue full"),
    INT_ATTR("motion_id", s.motion.traj.id, "id of the executing segment"),
    INT_ATTR("id", s.motion.traj.id, "id of the executing segment"),
    BOOL_ATTR("paused", s.motion.traj.paused, "motion paused"),
    BOOL_ATTR("single_stepping", s.motion.traj.single_stepping, "single-stepping"),
    FLOAT_ATTR("feedrate", s.motion.traj.scale, "feed override, 1.0 = 100 %"),
    FLOAT_ATTR("rapidrate", s.motion.traj.rapid_scale, "rapid override, 1.0 = 100 %"),
    FLOAT_ATTR("velocity", s.motion.traj.velocity, "default velocity"),
    FLOAT_ATTR("acceleration", s.motion.traj.acceleration, "default acceleration"),
    FLOAT_ATTR("max_velocity", s.motion.traj.maxVelocity, "maximum velocity"),
    FLOAT_ATTR("max_acceleration", s.motion.traj.maxAcceleration, "maximum acceleration"),
    BOOL_ATTR("probe_tripped", s.motion.traj.probe_tripped, "probe tripped (latched)"),
    BOOL_ATTR("probing", s.motion.traj.probing, "probe move in progress"),
    INT_ATTR("probe_val", s.motion.traj.probeval, "motion.probe-input"),
    INT_ATTR("kinematics_type", s.motion.traj.kinematics_type, "KINEMATICS_*"),
    INT_ATTR("motion_type", s.motion.traj.motion_type, "MOTION_TYPE_* of the executing move, 0 none"),
    FLOAT_ATTR("distance_to_go", s.motion.traj.distance_to_go, "remaining length of the move"),
    FLOAT_ATTR("current_vel", s.motion.traj.current_vel, "current velocity"),
    BOOL_ATTR("feed_override_enabled", s.motion.traj.feed_override_enabled, "feed override enabled"),
    BOOL_ATTR("adaptive_feed_enabled", s.motion.traj.adaptive_feed_enabled, "adaptive feed enabled"),
    BOOL_ATTR("feed_hold_enabled", s.motion.traj.feed_hold_enabled, "feed hold enabled"),
    INT_ATTR("num_extrajoints", s.motion.numExtraJoints, "extra joints"),
    BOOL_ATTR("external_offsets_applied", s.motion.external_offsets_applied, "external offsets in force"),
    UINT_ATTR("heartbeat", s.motion.heartbeat, "motion servo cycles"),
    INT_ATTR("pocket_prepped", s.io.tool.pocketPrepped, "tool-table index prepared by T, -1 none"),
    INT_ATTR("tool_in_spindle", s.io.tool.toolInSpindle, "tool number in the spindle, 0 none"),
    INT_ATTR("tool_from_pocket", s.io.tool.toolFromPocket, "pocket the spindle tool came from"),
    INT_ATTR("mist", s.io.coolant.mist, "MIST_ON or MIST_OFF"),
    INT_ATTR("flood", s.io.coolant.flood, "FLOOD_ON or FLOOD_OFF"),
    INT_ATTR("estop", s.io.aux.estop, "1 while in E-stop"),
    INT_ATTR("debug", s.debug, "debug flags"),
};

// Getter of a table attribute.
PyObject *stat_get(PyObject *self, void *closure)
{
    const StatAttr *attr = static_cast<const StatAttr *>(closure);
    return attr->get(reinterpret_cast<PyStat *>(self)->status);
}

// stat(): connect lazily to emcStatus; the copy starts all zero.
int stat_init(PyObject *self, PyObject *args, PyObject *kw)
{
    PyStat *st = reinterpret_cast<PyStat *>(self);
    if (!PyArg_ParseTuple(args, ":stat") || (kw && PyDict_Size(kw))) {
        if (!PyErr_Occurred()) PyErr_SetString(PyExc_TypeError, "stat() takes no keyword arguments");
        return -1;
    }
    delete st->link;
    memset(static_cast<void *>(&st->status), 0, sizeof st->status);
    st->link = new LcncLink("emcStatus");
    st->polled = 0;
    return 0;
}

// Free the link.
void stat_dealloc(PyObject *self)
{
    PyTypeObject *type = Py_TYPE(self);
    delete reinterpret_cast<PyStat *>(self)->link;
    type->tp_free(self);
    Py_DECREF(type);
}

// poll(): copy the current status (a consistent snapshot; never blocks task).
PyObject *stat_poll(PyObject *self, PyObject *)
{
    PyStat *st = reinterpret_cast<PyStat *>(self);
    if (!st->link) st->link = new LcncLink("emcStatus");
    if (!st->link->ready()) {
        PyErr_SetString(lcnc_error, "emcStatusBuffer invalid err=3");
        return nullptr;
    }
    if (lcnc_peek_status(*st->link, st->status) < 0) return nullptr;
    if (!st->polled) {
        st->polled = 1;
        lcnc_tool_attach();
    }
    Py_RETURN_NONE;
}

PyMethodDef stat_methods[] = {
    {"poll", stat_poll, METH_NOARGS, "poll(): update the attributes from the status buffer"},
    {"toolinfo", lcnc_stat_toolinfo, METH_VARARGS, "toolinfo(toolno) -> dict of the tool's data"},
    {nullptr, nullptr, 0, nullptr},
};

// The getset table: the scalar table, the computed attributes, tool_table.
std::vector<PyGetSetDef> &stat_getsets()
{
    static std::vector<PyGetSetDef> defs;
    if (!defs.empty()) return defs;
    for (const StatAttr &a : stat_attrs)
        defs.push_back({a.name, stat_get, nullptr, a.doc, const_cast<StatAttr *>(&a)});
    for (PyGetSetDef *g = lcnc_stat_tuple_getsets; g->name; g++) defs.push_back(*g);
    defs.push_back({"tool_table", lcnc_stat_tool_table, nullptr,
                    "tuple of linuxcnc.tool rows, index 0 = the spindle", nullptr});
    defs.push_back({nullptr, nullptr, nullptr, nullptr, nullptr});
    return defs;
}

} // namespace

// Create the stat type (subclassable) and add it.
int lcnc_add_stat(PyObject *module)
{
    PyType_Slot slots[] = {
        {Py_tp_init, reinterpret_cast<void *>(stat_init)},
        {Py_tp_dealloc, reinterpret_cast<void *>(stat_dealloc)},
        {Py_tp_new, reinterpret_cast<void *>(PyType_GenericNew)},
        {Py_tp_methods, stat_methods},
        {Py_tp_getset, stat_getsets().data()},
        {Py_tp_doc, const_cast<char *>("stat(): the controller's status; poll() refreshes it")},
        {0, nullptr},
    };
    PyType_Spec spec = {"linuxcnc.stat", sizeof(PyStat), 0,
                        Py_TPFLAGS_DEFAULT | Py_TPFLAGS_BASETYPE, slots};
    PyObject *type = PyType_FromSpec(&spec);
    if (!type) return -1;
    lcnc_stat_type = reinterpret_cast<PyTypeObject *>(type);
    return PyModule_AddObject(module, "stat", type) < 0 ? -1 : 0;
}
