// lcnc_stat_tuples.cc: stat attributes computed on access: pose tuples, per-joint/axis/spindle dicts, I/O tuples, G/M codes.
#include "lcnc_py.hh"

namespace {

// The status copy of a stat object.
const EMC_STAT &status_of(PyObject *self)
{
    return reinterpret_cast<PyStat *>(self)->status;
}

// Tuple of n items made by item(i); NULL on failure.
template <class F>
PyObject *tuple_of(int n, F item)
{
    PyObject *t = PyTuple_New(n);
    for (int i = 0; t && i < n; i++) {
        PyObject *v = item(i);
        if (!v) {
            Py_DECREF(t);
            return nullptr;
        }
        PyTuple_SET_ITEM(t, i, v);
    }
    return t;
}

// Set d[key] = value (stealing value); false on failure.
bool put(PyObject *d, const char *key, PyObject *value)
{
    if (!value) return false;
    int rc = PyDict_SetItemString(d, key, value);
    Py_DECREF(value);
    return rc == 0;
}

// The joint dictionary.
PyObject *joint_dict(const EMC_JOINT_STAT &j)
{
    PyObject *d = PyDict_New();
    bool ok = d && put(d, "jointType", PyLong_FromLong(j.jointType)) &&
              put(d, "units", PyFloat_FromDouble(j.units)) &&
              put(d, "backlash", PyFloat_FromDouble(j.backlash)) &&
              put(d, "min_position_limit", PyFloat_FromDouble(j.minPositionLimit)) &&
              put(d, "max_position_limit", PyFloat_FromDouble(j.maxPositionLimit)) &&
              put(d, "max_ferror", PyFloat_FromDouble(j.maxFerror)) &&
              put(d, "min_ferror", PyFloat_FromDouble(j.minFerror)) &&
              put(d, "ferror_current", PyFloat_FromDouble(j.ferrorCurrent)) &&
              put(d, "ferror_highmark", PyFloat_FromDouble(j.ferrorHighMark)) &&
              put(d, "output", PyFloat_FromDouble(j.output)) &&
              put(d, "input", PyFloat_FromDouble(j.input)) &&
              put(d, "velocity", PyFloat_FromDouble(j.velocity)) &&
              put(d, "inpos", PyLong_FromLong(j.inpos)) &&
              put(d, "homing", PyLong_FromLong(j.homing)) &&
              put(d, "homed", PyLong_FromLong(j.homed)) &&
              put(d, "fault", PyLong_FromLong(j.fault)) &&
              put(d, "enabled", PyLong_FromLong(j.enabled)) &&
              put(d, "min_soft_limit", PyLong_FromLong(j.minSoftLimit)) &&
              put(d, "max_soft_limit", PyLong_FromLong(j.maxSoftLimit)) &&
              put(d, "min_hard_limit", PyLong_FromLong(j.minHardLimit)) &&
              put(d, "max_hard_limit", PyLong_FromLong(j.maxHardLimit)) &&
              put(d, "override_limits", PyLong_FromLong(j.overrideLimits));
    if (!ok) Py_XDECREF(d);
    return ok ? d : nullptr;
}

// The axis dictionary.
PyObject *axis_dict(const EMC_AXIS_STAT &a)
{
    PyObject *d = PyDict_New();
    bool ok = d && put(d, "velocity", PyFloat_FromDouble(a.velocity)) &&
              put(d, "min_position_limit", PyFloat_FromDouble(a.minPositionLimit)) &&
              put(d, "max_position_limit", PyFloat_FromDouble(a.maxPositionLimit));
    if (!ok) Py_XDECREF(d);
    return ok ? d : nullptr;
}

// The spindle dictionary.
PyObject *spindle_dict(const EMC_SPINDLE_STAT &sp)
{
    PyObject *d = PyDict_New();
    bool ok = d && put(d, "brake", PyLong_FromLong(sp.brake)) &&
              put(d, "direction", PyLong_FromLong(sp.direction)) &&
              put(d, "enabled", PyLong_FromLong(sp.enabled)) &&
              put(d, "override_enabled", PyBool_FromLong(sp.spindle_override_enabled)) &&
              put(d, "speed", PyFloat_FromDouble(sp.speed)) &&
              put(d, "override", PyFloat_FromDouble(sp.spindle_scale)) &&
              put(d, "homed", PyBool_FromLong(sp.homed)) &&
              put(d, "orient_state", PyLong_FromLong(sp.orient_state)) &&
              put(d, "orient_fault", PyLong_FromLong(sp.orient_fault)) &&
              put(d, "increasing", PyLong_FromLong(sp.increasing));
    if (!ok) Py_XDECREF(d);
    return ok ? d : nullptr;
}

// Limit bitmask of a joint: 1 min hard, 2 max hard, 4 min soft, 8 max soft.
long limit_mask(const EMC_JOINT_STAT &j)
{
    return (j.minHardLimit ? 1 : 0) | (j.maxHardLimit ? 2 : 0) | (j.minSoftLimit ? 4 : 0) |
           (j.maxSoftLimit ? 8 : 0);
}

#define POSE_GETTER(fname, expr)                                          \
    PyObject *fname(PyObject *self, void *)                               \
    {                                                                     \
        const EMC_STAT &s = status_of(self);                              \
        return lcnc_pose_tuple(expr);                                     \
    }
POSE_GETTER(get_position, s.motion.traj.position)
POSE_GETTER(get_actual_position, s.motion.traj.actualPosition)
POSE_GETTER(get_probed_position, s.motion.traj.probedPosition)
POSE_GETTER(get_dtg, s.motion.traj.dtg)
POSE_GETTER(get_g5x_offset, s.task.g5x_offset)
POSE_GETTER(get_g92_offset, s.task.g92_offset)
POSE_GETTER(get_tool_offset, s.task.toolOffset)
POSE_GETTER(get_eoffset_pose, s.motion.eoffset_pose)
#undef POSE_GETTER

// A getter returning a tuple of n items, each item(s, i).
#define TUPLE_GETTER(fname, n, item)                                       \
    PyObject *fname(PyObject *self, void *)                                \
    {                                                                      \
        const EMC_STAT &s = status_of(self);                               \
        return tuple_of(n, [&s](int i) -> PyObject * { return item; });    \
    }
TUPLE_GETTER(get_joint_position, EMCMOT_MAX_JOINTS, PyFloat_FromDouble(s.motion.joint[i].output))
TUPLE_GETTER(get_joint_actual_position, EMCMOT_MAX_JOINTS, PyFloat_FromDouble(s.motion.joint[i].input))
TUPLE_GETTER(get_homed, EMCMOT_MAX_JOINTS, PyLong_FromLong(s.motion.joint[i].homed))
TUPLE_GETTER(get_limit, EMCMOT_MAX_JOINTS, PyLong_FromLong(limit_mask(s.motion.joint[i])))
TUPLE_GETTER(get_din, EMCMOT_MAX_DIO, PyLong_FromLong(s.motion.synch_di[i]))
TUPLE_GETTER(get_dout, EMCMOT_MAX_DIO, PyLong_FromLong(s.motion.synch_do[i]))
TUPLE_GETTER(get_ain, EMCMOT_MAX_AIO, PyFloat_FromDouble(s.motion.analog_input[i]))
TUPLE_GETTER(get_aout, EMCMOT_MAX_AIO, PyFloat_FromDouble(s.motion.analog_output[i]))
TUPLE_GETTER(get_misc_error, EMCMOT_MAX_MISC_ERROR, PyLong_FromLong(s.motion.misc_error[i]))
TUPLE_GETTER(get_gcodes, STATE_TAG_GCODES, PyLong_FromLong(s.task.activeGCodes[i]))
TUPLE_GETTER(get_mcodes, STATE_TAG_MCODES, PyLong_FromLong(s.task.activeMCodes[i]))
TUPLE_GETTER(get_settings, STATE_TAG_SETTINGS, PyFloat_FromDouble(s.task.activeSettings[i]))
TUPLE_GETTER(get_joint, EMCMOT_MAX_JOINTS, joint_dict(s.motion.joint[i]))
TUPLE_GETTER(get_axis, EMCMOT_MAX_AXIS, axis_dict(s.motion.axis[i]))
TUPLE_GETTER(get_spindle, EMCMOT_MAX_SPINDLES, spindle_dict(s.motion.spindle[i]))
#undef TUPLE_GETTER

// g5x_index: 1..9 (G54 = 1).
PyObject *get_g5x_index(PyObject *self, void *)
{
    return PyLong_FromLong(status_of(self).task.g5x_index);
}

} // namespace

PyGetSetDef lcnc_stat_tuple_getsets[] = {
    {"position", get_position, nullptr, "commanded position (9-tuple, machine coordinates)", nullptr},
    {"actual_position", get_actual_position, nullptr, "feedback position (9-tuple)", nullptr},
    {"probed_position", get_probed_position, nullptr, "where the probe tripped (9-tuple)", nullptr},
    {"dtg", get_dtg, nullptr, "distance to go per axis (9-tuple)", nullptr},
    {"g5x_offset", get_g5x_offset, nullptr, "active G54..G59.3 offset (9-tuple)", nullptr},
    {"g92_offset", get_g92_offset, nullptr, "G92 offset (9-tuple)", nullptr},
    {"tool_offset", get_tool_offset, nullptr, "tool length offset (9-tuple)", nullptr},
    {"eoffset_pose", get_eoffset_pose, nullptr, "external offsets (9-tuple)", nullptr},
    {"g5x_index", get_g5x_index, nullptr, "active coordinate system, G54 = 1", nullptr},
    {"joint_position", get_joint_position, nullptr, "commanded joint positions (16-tuple)", nullptr},
    {"joint_actual_position", get_joint_actual_position, nullptr, "feedback joint positions", nullptr},
    {"homed", get_homed, nullptr, "homed flag per joint (16-tuple of 0/1)", nullptr},
    {"limit", get_limit, nullptr, "limit bits per joint: 1 min hard, 2 max hard, 4 min soft, 8 max soft", nullptr},
    {"din", get_din, nullptr, "digital inputs (64-tuple)", nullptr},
    {"dout", get_dout, nullptr, "digital outputs (64-tuple)", nullptr},
    {"ain", get_ain, nullptr, "analog inputs (64-tuple)", nullptr},
    {"aout", get_aout, nullptr, "analog outputs (64-tuple)", nullptr},
    {"misc_error", get_misc_error, nullptr, "misc error codes (64-tuple)", nullptr},
    {"gcodes", get_gcodes, nullptr, "active G codes x10 (17-tuple)", nullptr},
    {"mcodes", get_mcodes, nullptr, "active M codes (10-tuple)", nullptr},
    {"settings", get_settings, nullptr, "sequence, F, S, G64 P, G64 Q", nullptr},
    {"joint", get_joint, nullptr, "16-tuple of joint dicts", nullptr},
    {"axis", get_axis, nullptr, "9-tuple of axis dicts", nullptr},
    {"spindle", get_spindle, nullptr, "8-tuple of spindle dicts", nullptr},
    {nullptr, nullptr, nullptr, nullptr, nullptr},
};
