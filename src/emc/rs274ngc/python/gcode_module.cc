// gcode_module.cc: the `gcode` Python module previews use: gcode.parse() runs a program through the
// interpreter into a Python canon object; strerror(), MIN_ERROR and arc_to_segments() go with it.
#include <cmath>
#include <cstdlib>
#include <string>

#include "../interp.hh"
#include "gcode_canon.hh"
#include "py_plugin.hh"

namespace {

// Tool-table rows gcode.parse asks the canon for, at most.
constexpr int MAX_TOOLS = 1000;
// Lines between two canon.check_abort() calls.
constexpr int ABORT_CHECK_LINES = 100;

// Text of the last error parse() met (what strerror() returns for error codes).
std::string &last_error()
{
    static std::string text;
    return text;
}

// canon.name(*args) when the canon has it; nullptr (no error) otherwise
PyObject *maybe_call(PyObject *canon, const char *name, PyObject *args)
{
    PyRef a(args);
    PyRef f(PyObject_GetAttrString(canon, name));
    if (!f) {
        PyErr_Clear();
        return nullptr;
    }
    PyObject *r = PyObject_Call(f.get(), a ? a.get() : PyTuple_New(0), nullptr);
    if (!r) PyErr_Clear();
    return r;
}

// one row of canon.get_tool(index): (toolno, x..w, diameter, frontangle, backangle, orientation)
bool tool_row(PyObject *canon, int index, CanonTool &t)
{
    PyRef r(maybe_call(canon, "get_tool", Py_BuildValue("(i)", index)));
    CanonPose &o = t.offset;
    if (!r || !PyTuple_Check(r.get()) ||
        !PyArg_ParseTuple(r.get(), "iddddddddddddi", &t.toolno, &o.x, &o.y, &o.z, &o.a, &o.b, &o.c, &o.u, &o.v,
                          &o.w, &t.diameter, &t.frontangle, &t.backangle, &t.orientation)) {
        PyErr_Clear();
        return false;
    }
    t.pocketno = index;
    return true;
}

// the tool table as the canon reports it (row 0 = spindle, until the first row without a tool)
std::vector<CanonTool> canon_tools(PyObject *canon)
{
    std::vector<CanonTool> tools(1);
    if (!tool_row(canon, 0, tools[0])) tools[0] = CanonTool();
    for (int i = 1; i < MAX_TOOLS; i++) {
        CanonTool t;
        if (!tool_row(canon, i, t) || t.toolno < 0) break;
        tools.push_back(t);
    }
    return tools;
}

// settings that come from the canon: parameter file, block delete, tool table
void configure(Interp &interp, PyObject *canon)
{
    PyRef pf(PyObject_GetAttrString(canon, "parameter_file"));
    if (pf && PyUnicode_Check(pf.get())) interp.set_var_file(py_str(pf.get()));
    PyErr_Clear();
    PyRef bd(maybe_call(canon, "get_block_delete", nullptr));
    interp.set_block_delete(bd && PyObject_IsTrue(bd.get()) == 1);
    PyErr_Clear();
    interp.set_tools(canon_tools(canon));
}

// true when canon.check_abort() asks to stop
bool abort_requested(PyObject *canon)
{
    PyRef r(maybe_call(canon, "check_abort", nullptr));
    return r && PyObject_IsTrue(r.get()) == 1;
}

// run the unit code, the init code and the file; returns the interpreter status of the last step
InterpStatus run_program(Interp &interp, PyObject *canon, const char *file, const char *unitcode,
                         const char *initcode)
{
    for (const char *code : {unitcode, initcode}) {
        if (!*code) continue;
        InterpStatus st = interp.execute_line(code);
        if (st == INTERP_ERROR) return st;
    }
    interp.open(file);
    for (long lines = 1;; lines++) {
        InterpStatus st = interp.execute_next();
        if (st == INTERP_EXIT || st == INTERP_ERROR) return st;
        if (lines % ABORT_CHECK_LINES == 0 && abort_requested(canon)) {
            last_error() = "Preview stopped: canon.check_abort() returned True";
            return INTERP_ERROR;
        }
    }
}

// gcode.parse(filename, canon, unitcode, initcode[, interpname]) -> (result, last sequence number)
PyObject *parse(PyObject *, PyObject *args)
{
    const char *file, *unitcode, *initcode, *interpname = "";
    PyObject *canon;
    if (!PyArg_ParseTuple(args, "sOss|s:parse", &file, &canon, &unitcode, &initcode, &interpname)) return nullptr;
    Py_INCREF(canon);
    PyRef keep(canon);
    PyCanon pc(canon);
    Interp interp(pc);
    pc.attach(&interp);
    last_error().clear();
    const char *ini = getenv("INI_FILE_NAME");
    if (ini && *ini) interp.load_ini(ini);
    configure(interp, canon);
    InterpStatus st;
    try {
        interp.init();
        st = run_program(interp, canon, file, unitcode, initcode);
        if (st == INTERP_ERROR && last_error().empty()) last_error() = interp.error_text();
    } catch (const InterpError &e) {
        last_error() = e.what();
        st = INTERP_ERROR;
    }
    if (pc.failed() && PyErr_Occurred()) return nullptr;
    return Py_BuildValue("(ii)", py_interp_code(st), interp.state().sequence_number);
}

// gcode.strerror(code): the message of the last parse error, or a name for other codes
PyObject *strerror_(PyObject *, PyObject *args)
{
    int code;
    if (!PyArg_ParseTuple(args, "i:strerror", &code)) return nullptr;
    static const char *const names[] = {"Interpreter returned OK", "Interpreter exited",
                                        "Interpreter must execute and finish", "End of file",
                                        "File not open", "Interpreter error"};
    if (code >= PY_INTERP_MIN_ERROR && !last_error().empty()) return PyUnicode_FromString(last_error().c_str());
    if (code >= 0 && code <= PY_INTERP_ERROR) return PyUnicode_FromString(names[code]);
    return PyUnicode_FromFormat("Unknown interpreter result %d", code);
}

// the canon's attribute as a float (0 when missing)
double attr_double(PyObject *o, const char *name)
{
    PyRef v(PyObject_GetAttrString(o, name));
    double d = v ? PyFloat_AsDouble(v.get()) : 0.0;
    if (PyErr_Occurred()) {
        PyErr_Clear();
        return 0.0;
    }
    return d;
}

// gcode.arc_to_segments(canon, end1, end2, c1, c2, rot, axis_end, a, b, c, u, v, w[, divisions]):
// the arc from canon.lo (9 values) in canon.plane as 9-tuples, `divisions` per full turn
PyObject *arc_to_segments(PyObject *, PyObject *args)
{
    PyObject *canon;
    double e1, e2, c1, c2, ae, rest[6];
    int rot, divisions = 64;
    if (!PyArg_ParseTuple(args, "Oddddiddddddd|i:arc_to_segments", &canon, &e1, &e2, &c1, &c2, &rot, &ae,
                          &rest[0], &rest[1], &rest[2], &rest[3], &rest[4], &rest[5], &divisions))
        return nullptr;
    PyRef lo(PyObject_GetAttrString(canon, "lo"));
    double start[9] = {};
    if (!lo || !PySequence_Check(lo.get()) || PySequence_Size(lo.get()) < 9) {
        PyErr_Clear();
        PyErr_SetString(PyExc_AttributeError, "arc_to_segments: the canon needs 'lo', the last position (9 values)");
        return nullptr;
    }
    for (int k = 0; k < 9; k++) {
        PyRef item(PySequence_GetItem(lo.get(), k));
        start[k] = item ? PyFloat_AsDouble(item.get()) : 0.0;
    }
    int plane = (int)attr_double(canon, "plane");
    int X = plane == CANON_PLANE_YZ ? 1 : plane == CANON_PLANE_XZ ? 2 : 0;
    int Y = (X + 1) % 3, Z = (X + 2) % 3;
    double a0 = atan2(start[Y] - c2, start[X] - c1), a1 = atan2(e2 - c2, e1 - c1);
    double r0 = hypot(start[X] - c1, start[Y] - c2), r1 = hypot(e1 - c1, e2 - c2);
    double sweep = a1 - a0;
    if (rot > 0 && sweep <= 0) sweep += 2 * M_PI;
    if (rot < 0 && sweep >= 0) sweep -= 2 * M_PI;
    sweep += (rot > 0 ? 1 : -1) * 2 * M_PI * (std::abs(rot) - 1);
    int steps = std::max(1, (int)std::ceil(std::fabs(sweep) / (2 * M_PI) * std::max(divisions, 1)));
    PyObject *segs = PyList_New(steps);
    for (int s = 1; segs && s <= steps; s++) {
        double f = (double)s / steps, ang = a0 + sweep * f, r = r0 + (r1 - r0) * f, p[9];
        p[X] = c1 + r * cos(ang);
        p[Y] = c2 + r * sin(ang);
        p[Z] = start[Z] + (ae - start[Z]) * f;
        for (int k = 3; k < 9; k++) p[k] = start[k] + (rest[k - 3] - start[k]) * f;
        if (s == steps) { p[X] = e1; p[Y] = e2; }
        PyList_SET_ITEM(segs, s - 1, Py_BuildValue("(ddddddddd)", p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8]));
    }
    return segs;
}

PyMethodDef METHODS[] = {
    {"parse", parse, METH_VARARGS,
     "parse(filename, canon, unitcode, initcode[, interpname]) -> (result, last sequence number)"},
    {"strerror", strerror_, METH_VARARGS, "strerror(result) -> message"},
    {"arc_to_segments", arc_to_segments, METH_VARARGS,
     "arc_to_segments(canon, end1, end2, center1, center2, rotation, axis_end, a, b, c, u, v, w[, per_turn])"},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef MODULE = {PyModuleDef_HEAD_INIT, "gcode", "RS274NGC programs through the interpreter into a Python canon",
                      -1, METHODS, nullptr, nullptr, nullptr, nullptr};

} // namespace

// Module entry point.
PyMODINIT_FUNC PyInit_gcode()
{
    PyObject *m = PyModule_Create(&MODULE);
    if (!m) return nullptr;
    PyModule_AddIntConstant(m, "MIN_ERROR", PY_INTERP_MIN_ERROR);
    PyModule_AddIntConstant(m, "INTERP_OK", PY_INTERP_OK);
    PyModule_AddIntConstant(m, "INTERP_EXIT", PY_INTERP_EXIT);
    PyModule_AddIntConstant(m, "INTERP_EXECUTE_FINISH", PY_INTERP_EXECUTE_FINISH);
    PyModule_AddIntConstant(m, "INTERP_ENDFILE", PY_INTERP_ENDFILE);
    PyModule_AddIntConstant(m, "INTERP_ERROR", PY_INTERP_ERROR);
    return m;
}
