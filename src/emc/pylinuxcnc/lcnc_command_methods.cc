// lcnc_command_methods.cc: the methods of linuxcnc.command: argument checks, LinuxCNC's error texts, one message each.
#include "lcnc_command.hh"

#include <cstring>

namespace {

// ---- generic handlers generated from the message class and field

// A command without arguments.
template <class M>
PyObject *plain(PyObject *self, PyObject *)
{
    M m;
    return lcnc_command_send(self, m);
}

// A command taking one int into Field.
template <class M, auto Field>
PyObject *one_int(PyObject *self, PyObject *args)
{
    int v = 0;
    if (!PyArg_ParseTuple(args, "i", &v)) return nullptr;
    M m;
    m.*Field = static_cast<std::remove_reference_t<decltype(m.*Field)>>(v);
    return lcnc_command_send(self, m);
}

// A command taking one double into Field; negative values become 0 (overrides, maxvel).
template <class M, auto Field>
PyObject *one_scale(PyObject *self, PyObject *args)
{
    double v = 0;
    if (!PyArg_ParseTuple(args, "d", &v)) return nullptr;
    M m;
    m.*Field = v < 0 ? 0.0 : v;
    return lcnc_command_send(self, m);
}

// A joint command: (joint).
template <class M>
PyObject *joint_only(PyObject *self, PyObject *args)
{
    return one_int<M, &M::joint>(self, args);
}

// A joint command with one double: (joint, value).
template <class M, auto Field>
PyObject *joint_value(PyObject *self, PyObject *args)
{
    int joint = 0;
    double v = 0;
    if (!PyArg_ParseTuple(args, "id", &joint, &v)) return nullptr;
    M m;
    m.joint = joint;
    m.*Field = v;
    return lcnc_command_send(self, m);
}

// A text command (operator messages, MDI): longer than LINELEN - 1 is truncated.
template <class M, auto Field>
PyObject *text_msg(PyObject *self, PyObject *args)
{
    const char *text = nullptr;
    if (!PyArg_ParseTuple(args, "s", &text)) return nullptr;
    M m;
    emc_set_text(m.*Field, text);
    return lcnc_command_send(self, m);
}

// A per-spindle on/off flag: (flag[, spindle=0]).
template <class M>
PyObject *spindle_flag(PyObject *self, PyObject *args)
{
    int flag = 0, spindle = 0;
    if (!PyArg_ParseTuple(args, "i|i", &flag, &spindle)) return nullptr;
    M m;
    m.mode = static_cast<uint8_t>(flag != 0);
    m.spindle = spindle;
    return lcnc_command_send(self, m);
}

// Raise ValueError(text); NULL.
PyObject *value_error(const char *text)
{
    PyErr_SetString(PyExc_ValueError, text);
    return nullptr;
}

// ---- commands with their own checks

PyObject *mode(PyObject *self, PyObject *args)
{
    int v = 0;
    if (!PyArg_ParseTuple(args, "i", &v)) return nullptr;
    if (v != EMC_TASK_MODE_MDI && v != EMC_TASK_MODE_MANUAL && v != EMC_TASK_MODE_AUTO)
        return value_error("Mode should be MODE_MDI, MODE_MANUAL, or MODE_AUTO");
    EMC_TASK_SET_MODE m;
    m.mode = v;
    return lcnc_command_send(self, m);
}

PyObject *state(PyObject *self, PyObject *args)
{
    int v = 0;
    if (!PyArg_ParseTuple(args, "i", &v)) return nullptr;
    if (v < EMC_TASK_STATE_ESTOP || v > EMC_TASK_STATE_ON)
        return value_error("Machine state should be STATE_ESTOP, STATE_ESTOP_RESET, STATE_ON, "
                           "or STATE_OFF");
    EMC_TASK_SET_STATE m;
    m.state = v;
    return lcnc_command_send(self, m);
}

// On/off command pair chosen by the argument.
template <class On, class Off>
PyObject *on_off(PyObject *self, PyObject *args, const char *error)
{
    int v = 0;
    if (!PyArg_ParseTuple(args, "i", &v)) return nullptr;
    if (v == LCNC_COOLANT_ON) return plain<On>(self, nullptr);
    if (v == LCNC_COOLANT_OFF) return plain<Off>(self, nullptr);
    return value_error(error);
}

PyObject *flood(PyObject *self, PyObject *args)
{
    return on_off<EMC_COOLANT_FLOOD_ON, EMC_COOLANT_FLOOD_OFF>(self, args,
                                                               "FLOOD should be FLOOD_ON or FLOOD_OFF");
}

PyObject *mist(PyObject *self, PyObject *args)
{
    return on_off<EMC_COOLANT_MIST_ON, EMC_COOLANT_MIST_OFF>(self, args,
                                                             "Mist should be MIST_ON or MIST_OFF");
}

PyObject *brake(PyObject *self, PyObject *args)
{
    int v = 0, spindle = 0;
    if (!PyArg_ParseTuple(args, "i|i", &v, &spindle)) return nullptr;
    if (v == LCNC_BRAKE_ENGAGE) {
        EMC_SPINDLE_BRAKE_ENGAGE m;
        m.spindle = spindle;
        return lcnc_command_send(self, m);
    }
    if (v == LCNC_BRAKE_RELEASE) {
        EMC_SPINDLE_BRAKE_RELEASE m;
        m.spindle = spindle;
        return lcnc_command_send(self, m);
    }
    return value_error("BRAKE should be BRAKE_ENGAGE or BRAKE_RELEASE");
}

PyObject *mdi(PyObject *self, PyObject *args)
{
    const char *text = nullptr;
    Py_ssize_t len = 0;
    if (!PyArg_ParseTuple(args, "s#", &text, &len)) return nullptr;
    if (len > LINELEN - 1) return value_error("MDI commands limited to 254 characters");
    EMC_TASK_PLAN_EXECUTE m;
    emc_set_text(m.command, text);
    return lcnc_command_send(self, m);
}

// PLAN_CLOSE first (it uses a serial even when the name is then refused), then PLAN_OPEN.
PyObject *program_open(PyObject *self, PyObject *args)
{
    const char *path = nullptr;
    Py_ssize_t len = 0;
    if (!PyArg_ParseTuple(args, "s#", &path, &len)) return nullptr;
    EMC_TASK_PLAN_CLOSE close_msg;
    PyObject *rc = lcnc_command_send(self, close_msg);
    if (!rc) return nullptr;
    Py_DECREF(rc);
    if (len > LINELEN - 1) return value_error("File name limited to 254 characters");
    EMC_TASK_PLAN_OPEN m;
    emc_set_text(m.file, path);
    return lcnc_command_send(self, m);
}

// auto(AUTO_RUN, line) / auto(AUTO_PAUSE | RESUME | STEP | REVERSE | FORWARD).
PyObject *auto_cmd(PyObject *self, PyObject *args)
{
    int what = 0, line = 0;
    if (!PyArg_ParseTuple(args, "i|i", &what, &line)) return nullptr;
    Py_ssize_t n = PyTuple_Size(args);
    if (what == LCNC_AUTO_RUN && n == 2) {
        EMC_TASK_PLAN_RUN m;
        m.line = line;
        return lcnc_command_send(self, m);
    }
    if (what < LCNC_AUTO_PAUSE || what > LCNC_AUTO_FORWARD) {
        PyErr_Format(lcnc_error, "Unexpected argument '%d' to command.auto", what);
        return nullptr;
    }
    if (n != 1) {
        PyErr_Format(PyExc_TypeError, "function takes exactly 1 argument (%zd given)", n);
        return nullptr;
    }
    switch (what) {
    case LCNC_AUTO_PAUSE: return plain<EMC_TASK_PLAN_PAUSE>(self, nullptr);
    case LCNC_AUTO_RESUME: return plain<EMC_TASK_PLAN_RESUME>(self, nullptr);
    case LCNC_AUTO_STEP: return plain<EMC_TASK_PLAN_STEP>(self, nullptr);
    case LCNC_AUTO_REVERSE: return plain<EMC_TASK_PLAN_REVERSE>(self, nullptr);
    default: return plain<EMC_TASK_PLAN_FORWARD>(self, nullptr);
    }
}

// spindle(dir[, speed[, spindle[, wait]]]) for FORWARD/REVERSE; spindle(dir[, spindle]) else.
PyObject *spindle(PyObject *self, PyObject *args)
{
    int dir = 0, spindle_no = 0, wait = 0;
    PyObject *second = nullptr;
    if (!PyArg_ParseTuple(args, "i|Oii", &dir, &second, &spindle_no, &wait)) return nullptr;
    if (dir == LCNC_SPINDLE_FORWARD || dir == LCNC_SPINDLE_REVERSE) {
        double speed = second ? PyFloat_AsDouble(second) : 0.0;
        if (PyErr_Occurred()) return nullptr;
        EMC_SPINDLE_ON m;
        m.spindle = spindle_no;
        m.speed = dir * speed;
        m.wait_for_spindle_at_speed = wait;
        return lcnc_command_send(self, m);
    }
    if (PyTuple_Size(args) > 2) {
        PyErr_SetString(PyExc_TypeError, "spindle(dir, spindle) takes at most 2 arguments for this direction");
        return nullptr;
    }
    long which = second ? PyLong_AsLong(second) : 0;
    if (PyErr_Occurred()) return nullptr;
    switch (dir) {
    case LCNC_SPINDLE_OFF: { EMC_SPINDLE_OFF m; m.spindle = static_cast<int32_t>(which); return lcnc_command_send(self, m); }
    case LCNC_SPINDLE_INCREASE: { EMC_SPINDLE_INCREASE m; m.spindle = static_cast<int32_t>(which); return lcnc_command_send(self, m); }
    case LCNC_SPINDLE_DECREASE: { EMC_SPINDLE_DECREASE m; m.spindle = static_cast<int32_t>(which); return lcnc_command_send(self, m); }
    case LCNC_SPINDLE_CONSTANT: { EMC_SPINDLE_CONSTANT m; m.spindle = static_cast<int32_t>(which); return lcnc_command_send(self, m); }
    default:
        return value_error("Spindle direction should be SPINDLE_FORWARD, SPINDLE_REVERSE, "
                           "SPINDLE_OFF, SPINDLE_INCREASE, SPINDLE_DECREASE, or SPINDLE_CONSTANT");
    }
}

// Arguments a jog form takes, and a TypeError when the count is wrong.
bool jog_arity(const char *name, Py_ssize_t want, Py_ssize_t got)
{
    if (want == got) return true;
    PyErr_Format(PyExc_TypeError, "jog(%s, ...) takes %zd arguments (%zd given)", name, want, got);
    return false;
}

// jog(JOG_STOP, jjogmode, n) / (JOG_CONTINUOUS, ..., vel) / (JOG_INCREMENT, ..., vel, incr).
PyObject *jog(PyObject *self, PyObject *args)
{
    Py_ssize_t n = PyTuple_Size(args);
    int what = 0, index = 0;
    PyObject *jjog = nullptr;
    double vel = 0, incr = 0;
    long first = n >= 1 ? PyLong_AsLong(PyTuple_GET_ITEM(args, 0)) : -1;
    if (n < 1 || (first == -1 && PyErr_Occurred())) {
        PyErr_Clear();
        PyErr_SetString(PyExc_TypeError, "jog() first argument must be JOG_xxx");
        return nullptr;
    }
    what = static_cast<int>(first);
    if (what == LCNC_JOG_STOP) {
        if (!jog_arity("JOG_STOP", 3, n) || !PyArg_ParseTuple(args, "iOi", &what, &jjog, &index)) return nullptr;
        EMC_JOG_STOP m;
        m.joint_or_axis = index;
        m.jjogmode = PyObject_IsTrue(jjog) ? EMC_JOG_JOINT : EMC_JOG_AXIS;
        return lcnc_command_send(self, m);
    }
    if (what == LCNC_JOG_CONTINUOUS) {
        if (!jog_arity("JOG_CONTINUOUS", 4, n) || !PyArg_ParseTuple(args, "iOid", &what, &jjog, &index, &vel))
            return nullptr;
        EMC_JOG_CONT m;
        m.joint_or_axis = index;
        m.jjogmode = PyObject_IsTrue(jjog) ? EMC_JOG_JOINT : EMC_JOG_AXIS;
        m.vel = vel;
        return lcnc_command_send(self, m);
    }
    if (what == LCNC_JOG_INCREMENT) {
        if (!jog_arity("JOG_INCREMENT", 5, n) ||
            !PyArg_ParseTuple(args, "iOidd", &what, &jjog, &index, &vel, &incr))
            return nullptr;
        EMC_JOG_INCR m;
        m.joint_or_axis = index;
        m.jjogmode = PyObject_IsTrue(jjog) ? EMC_JOG_JOINT : EMC_JOG_AXIS;
        m.vel = vel;
        m.incr = incr;
        return lcnc_command_send(self, m);
    }
    PyErr_SetString(PyExc_TypeError, "jog() first argument must be JOG_xxx");
    return nullptr;
}

PyObject *spindleoverride(PyObject *self, PyObject *args)
{
    double scale = 0;
    int spindle_no = 0;
    if (!PyArg_ParseTuple(args, "d|i", &scale, &spindle_no)) return nullptr;
    EMC_TRAJ_SET_SPINDLE_SCALE m;
    m.scale = scale < 0 ? 0.0 : scale;
    m.spindle = spindle_no;
    return lcnc_command_send(self, m);
}

PyObject *set_digital_output(PyObject *self, PyObject *args)
{
    unsigned char index = 0, value = 0;
    if (!PyArg_ParseTuple(args, "bb", &index, &value)) return nullptr;
    EMC_MOTION_SET_DOUT m;
    m.index = index;
    m.start = m.end = value;
    m.now = 1;
    return lcnc_command_send(self, m);
}

PyObject *set_analog_output(PyObject *self, PyObject *args)
{
    unsigned char index = 0;
    double value = 0;
    if (!PyArg_ParseTuple(args, "bd", &index, &value)) return nullptr;
    EMC_MOTION_SET_AOUT m;
    m.index = index;
    m.start = m.end = value;
    m.now = 1;
    return lcnc_command_send(self, m);
}

PyObject *load_tool_table(PyObject *self, PyObject *)
{
    EMC_TOOL_LOAD_TOOL_TABLE m; // empty file: the INI's tool table
    return lcnc_command_send(self, m);
}

PyObject *override_limits(PyObject *self, PyObject *)
{
    EMC_JOINT_OVERRIDE_LIMITS m;
    m.joint = 0;
    return lcnc_command_send(self, m);
}

// tool_offset(toolno, z, x, diameter, frontangle, backangle, orientation). The message names
// the tool's own row (found in the published tool data), -1 when the tool is not there yet.
PyObject *tool_offset(PyObject *self, PyObject *args)
{
    int toolno = 0, orientation = 0;
    double z = 0, x = 0, diameter = 0, front = 0, back = 0;
    if (!PyArg_ParseTuple(args, "idddddi", &toolno, &z, &x, &diameter, &front, &back, &orientation))
        return nullptr;
    EMC_TOOL_SET_OFFSET m;
    char err[128];
    tooldata_t *td = tooldata_open(0, err, sizeof err);
    int index = td ? tooldata_find(td, toolno, nullptr) : -1;
    tooldata_close(td);
    m.pocket = index > 0 ? index : -1;
    m.toolno = toolno;
    m.offset.tran.z = z;
    m.offset.tran.x = x;
    m.diameter = diameter;
    m.frontangle = front;
    m.backangle = back;
    m.orientation = orientation;
    return lcnc_command_send(self, m);
}

#define M_NOARGS(name, fn, doc) {name, reinterpret_cast<PyCFunction>(fn), METH_NOARGS, doc}
#define M_ARGS(name, fn, doc) {name, reinterpret_cast<PyCFunction>(fn), METH_VARARGS, doc}

} // namespace

// The method table.
std::vector<PyMethodDef> lcnc_command_methods()
{
    return {
        M_NOARGS("abort", plain<EMC_TASK_ABORT>, "abort(): stop motion and the program"),
        M_ARGS("auto", auto_cmd, "auto(AUTO_RUN, line) or auto(AUTO_PAUSE|RESUME|STEP|REVERSE|FORWARD)"),
        M_ARGS("brake", brake, "brake(BRAKE_ENGAGE|BRAKE_RELEASE[, spindle])"),
        M_ARGS("debug", (one_int<EMC_SET_DEBUG, &EMC_SET_DEBUG::debug>), "debug(flags)"),
        M_ARGS("display_msg", (text_msg<EMC_OPERATOR_DISPLAY, &EMC_OPERATOR_DISPLAY::display>), "display_msg(text)"),
        M_ARGS("error_msg", (text_msg<EMC_OPERATOR_ERROR, &EMC_OPERATOR_ERROR::error>), "error_msg(text)"),
        M_ARGS("text_msg", (text_msg<EMC_OPERATOR_TEXT, &EMC_OPERATOR_TEXT::text>), "text_msg(text)"),
        M_ARGS("feedrate", (one_scale<EMC_TRAJ_SET_SCALE, &EMC_TRAJ_SET_SCALE::scale>), "feedrate(scale)"),
        M_ARGS("rapidrate", (one_scale<EMC_TRAJ_SET_RAPID_SCALE, &EMC_TRAJ_SET_RAPID_SCALE::scale>), "rapidrate(scale)"),
        M_ARGS("maxvel", (one_scale<EMC_TRAJ_SET_MAX_VELOCITY, &EMC_TRAJ_SET_MAX_VELOCITY::velocity>), "maxvel(velocity)"),
        M_ARGS("spindleoverride", spindleoverride, "spindleoverride(scale[, spindle])"),
        M_ARGS("flood", flood, "flood(FLOOD_ON|FLOOD_OFF)"),
        M_ARGS("mist", mist, "mist(MIST_ON|MIST_OFF)"),
        M_ARGS("home", joint_only<EMC_JOINT_HOME>, "home(joint), -1 = all"),
        M_ARGS("unhome", joint_only<EMC_JOINT_UNHOME>, "unhome(joint), -1 all, -2 volatile"),
        M_ARGS("jog", jog, "jog(JOG_STOP|JOG_CONTINUOUS|JOG_INCREMENT, jjogmode, index[, vel[, incr]])"),
        M_NOARGS("load_tool_table", load_tool_table, "load_tool_table(): reload the tool table"),
        M_ARGS("mdi", mdi, "mdi(text)"),
        M_ARGS("mode", mode, "mode(MODE_MANUAL|MODE_AUTO|MODE_MDI)"),
        M_ARGS("state", state, "state(STATE_ESTOP|STATE_ESTOP_RESET|STATE_ON|STATE_OFF)"),
        M_NOARGS("override_limits", override_limits, "override_limits()"),
        M_ARGS("program_open", program_open, "program_open(path)"),
        M_NOARGS("reset_interpreter", plain<EMC_TASK_PLAN_INIT>, "reset_interpreter()"),
        M_NOARGS("task_plan_synch", plain<EMC_TASK_PLAN_SYNCH>, "task_plan_synch()"),
        M_NOARGS("task_plan_sync", plain<EMC_TASK_PLAN_SYNCH>, "task_plan_sync() (alias)"),
        M_ARGS("set_adaptive_feed", (one_int<EMC_MOTION_ADAPTIVE, &EMC_MOTION_ADAPTIVE::status>), "set_adaptive_feed(0|1)"),
        M_ARGS("set_analog_output", set_analog_output, "set_analog_output(index, value)"),
        M_ARGS("set_digital_output", set_digital_output, "set_digital_output(index, value)"),
        M_ARGS("set_block_delete", (one_int<EMC_TASK_PLAN_SET_BLOCK_DELETE, &EMC_TASK_PLAN_SET_BLOCK_DELETE::state>), "set_block_delete(0|1)"),
        M_ARGS("set_optional_stop", (one_int<EMC_TASK_PLAN_SET_OPTIONAL_STOP, &EMC_TASK_PLAN_SET_OPTIONAL_STOP::state>), "set_optional_stop(0|1)"),
        M_ARGS("set_feed_hold", (one_int<EMC_TRAJ_SET_FH_ENABLE, &EMC_TRAJ_SET_FH_ENABLE::mode>), "set_feed_hold(0|1)"),
        M_ARGS("set_feed_override", (one_int<EMC_TRAJ_SET_FO_ENABLE, &EMC_TRAJ_SET_FO_ENABLE::mode>), "set_feed_override(0|1)"),
        M_ARGS("set_spindle_override", spindle_flag<EMC_TRAJ_SET_SO_ENABLE>, "set_spindle_override(0|1[, spindle])"),
        M_ARGS("set_min_limit", (joint_value<EMC_JOINT_SET_MIN_POSITION_LIMIT, &EMC_JOINT_SET_MIN_POSITION_LIMIT::limit>), "set_min_limit(joint, limit)"),
        M_ARGS("set_max_limit", (joint_value<EMC_JOINT_SET_MAX_POSITION_LIMIT, &EMC_JOINT_SET_MAX_POSITION_LIMIT::limit>), "set_max_limit(joint, limit)"),
        M_ARGS("spindle", spindle, "spindle(direction[, speed[, spindle[, wait]]])"),
        M_ARGS("teleop_enable", (one_int<EMC_TRAJ_SET_TELEOP_ENABLE, &EMC_TRAJ_SET_TELEOP_ENABLE::enable>), "teleop_enable(0|1)"),
        M_ARGS("traj_mode", (one_int<EMC_TRAJ_SET_MODE, &EMC_TRAJ_SET_MODE::mode>), "traj_mode(TRAJ_MODE_*)"),
        M_ARGS("tool_offset", tool_offset, "tool_offset(toolno, z, x, diameter, frontangle, backangle, orientation)"),
        {nullptr, nullptr, 0, nullptr},
    };
}
