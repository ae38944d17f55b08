// gcode_canon.cc: forwards canon calls to the Python canon of gcode.parse (the calls previews draw from).
#include <cmath>

#include "../interp.hh"
#include "gcode_canon.hh"

namespace {

// Line segments a NURBS curve is drawn with, per control point.
constexpr int NURBS_SEGMENTS_PER_POINT = 16;

// Cox-de Boor basis N(i,k) on a clamped uniform knot vector with n control points.
double basis(int i, int k, double u, const std::vector<double> &knots)
{
    if (k == 1) {
        bool last = u >= knots.back() && knots[i + 1] >= knots.back() && knots[i] < knots[i + 1];
        return (u >= knots[i] && u < knots[i + 1]) || last ? 1.0 : 0.0;
    }
    double a = 0, b = 0;
    double d1 = knots[i + k - 1] - knots[i], d2 = knots[i + k] - knots[i + 1];
    if (d1 > 0) a = (u - knots[i]) / d1 * basis(i, k - 1, u, knots);
    if (d2 > 0) b = (knots[i + k] - u) / d2 * basis(i + 1, k - 1, u, knots);
    return a + b;
}

// the knot vector LinuxCNC's G5.2 uses: clamped, uniform
std::vector<double> clamped_knots(int n, int k)
{
    std::vector<double> knots;
    for (int i = 0; i < n + k; i++)
        knots.push_back(i < k ? 0.0 : i >= n ? (double)(n - k + 1) : (double)(i - k + 1));
    return knots;
}

} // namespace

// Report a new source line to the canon (next_line(linecode)) before its first call.
void PyCanon::next_line()
{
    if (!interp_ || failed_) return;
    int seq = interp_->state().sequence_number;
    if (seq == last_line_) return;
    last_line_ = seq;
    int g[17], m[10];
    double s[5];
    interp_->active_g_codes(g);
    interp_->active_m_codes(m);
    interp_->active_settings(s);
    PyRef gt(PyTuple_New(17)), mt(PyTuple_New(10));
    for (int k = 0; gt && k < 17; k++) PyTuple_SET_ITEM(gt.get(), k, PyLong_FromLong(g[k]));
    for (int k = 0; mt && k < 10; k++) PyTuple_SET_ITEM(mt.get(), k, PyLong_FromLong(m[k]));
    PyRef types(PyImport_ImportModule("types"));
    PyRef ns(types ? PyObject_GetAttrString(types.get(), "SimpleNamespace") : nullptr);
    PyRef kw(Py_BuildValue("{s:i,s:O,s:O,s:(ddddd)}", "sequence_number", seq, "gcodes", gt.get(), "mcodes",
                           mt.get(), "settings", s[0], s[1], s[2], s[3], s[4]));
    PyRef empty(PyTuple_New(0));
    PyRef code(ns && kw ? PyObject_Call(ns.get(), empty.get(), kw.get()) : nullptr);
    if (!code) {
        failed_ = true;
        return;
    }
    PyRef r(PyObject_CallMethod(canon_, "next_line", "O", code.get()));
    if (!r) failed_ = true;
}

// canon.method(*args), consuming args; a failure is remembered and stops the parse
void PyCanon::call(const char *method, PyObject *args)
{
    PyRef a(args);
    if (!a) failed_ = true;
    if (!failed_) next_line();
    if (failed_) throw InterpError(std::string("Python canon method ") + method + " failed");
    PyRef f(PyObject_GetAttrString(canon_, method));
    PyRef r(f ? PyObject_Call(f.get(), a.get(), nullptr) : nullptr);
    if (!r) {
        failed_ = true;
        throw InterpError(std::string("Python canon method ") + method + " failed");
    }
}

// canon.method(x, y, z, a, b, c, u, v, w)
void PyCanon::call_pose(const char *method, const CanonPose &p)
{
    call(method, Py_BuildValue("(ddddddddd)", p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w));
}

void PyCanon::set_g5x_offset(int origin, const CanonPose &p)
{
    call("set_g5x_offset", Py_BuildValue("(iddddddddd)", origin, p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w));
}

void PyCanon::set_g92_offset(const CanonPose &p) { call_pose("set_g92_offset", p); }
void PyCanon::set_xy_rotation(double deg) { call("set_xy_rotation", Py_BuildValue("(d)", deg)); }

void PyCanon::select_plane(CanonPlane p)
{
    plane_ = p;
    call("set_plane", Py_BuildValue("(i)", (int)p));
}

void PyCanon::set_feed_rate(double rate) { call("set_feed_rate", Py_BuildValue("(d)", rate)); }

void PyCanon::straight_traverse(int, const CanonPose &p)
{
    last_ = p;
    call_pose("straight_traverse", p);
}

void PyCanon::straight_feed(int, const CanonPose &p)
{
    last_ = p;
    call_pose("straight_feed", p);
}

void PyCanon::straight_probe(int, const CanonPose &p, int)
{
    last_ = p;
    call_pose("straight_probe", p);
}

void PyCanon::rigid_tap(int, double x, double y, double z, double)
{
    call("rigid_tap", Py_BuildValue("(ddd)", x, y, z));
}

void PyCanon::arc_feed(int, double first_end, double second_end, double first_axis, double second_axis,
                       int rotation, double axis_end, double a, double b, double c, double u, double v,
                       double w)
{
    double *ends[3][3] = {{&last_.x, &last_.y, &last_.z}, {&last_.y, &last_.z, &last_.x},
                          {&last_.z, &last_.x, &last_.y}};
    int row = plane_ == CANON_PLANE_YZ ? 1 : plane_ == CANON_PLANE_XZ ? 2 : 0;
    *ends[row][0] = first_end;
    *ends[row][1] = second_end;
    *ends[row][2] = axis_end;
    last_.a = a; last_.b = b; last_.c = c; last_.u = u; last_.v = v; last_.w = w;
    call("arc_feed", Py_BuildValue("(ddddiddddddd)", first_end, second_end, first_axis, second_axis, rotation,
                                   axis_end, a, b, c, u, v, w));
}

void PyCanon::dwell(double seconds) { call("dwell", Py_BuildValue("(d)", seconds)); }

// G5/G5.1/G5.2: drawn as straight feeds along the curve (clamped uniform NURBS, in the XY plane).
void PyCanon::nurbs_g5_feed(int line, const std::vector<CanonNurbsPoint> &pts, unsigned order, CanonPlane)
{
    int n = (int)pts.size(), k = (int)order;
    if (n < 2 || k < 2 || k > n) return;
    std::vector<double> knots = clamped_knots(n, k);
    int steps = (n - 1) * NURBS_SEGMENTS_PER_POINT;
    for (int s = 1; s <= steps; s++) {
        double u = knots.back() * s / steps, x = 0, y = 0, wsum = 0;
        for (int i = 0; i < n; i++) {
            double nb = basis(i, k, u, knots) * pts[i].weight;
            x += nb * pts[i].x;
            y += nb * pts[i].y;
            wsum += nb;
        }
        if (wsum <= 0) continue;
        CanonPose p = last_;
        p.x = x / wsum;
        p.y = y / wsum;
        straight_feed(line, p);
    }
}

void PyCanon::change_tool() { call("change_tool", Py_BuildValue("(i)", interp_ ? interp_->state().selected_pocket : 0)); }
void PyCanon::use_tool_length_offset(const CanonPose &p) { call_pose("tool_offset", p); }
void PyCanon::comment(const std::string &text) { call("comment", Py_BuildValue("(s)", text.c_str())); }
void PyCanon::message(const std::string &text) { call("message", Py_BuildValue("(s)", text.c_str())); }

// canon.get_external_length_units(): mm per machine unit as the preview's machine has it
double PyCanon::get_external_length_units()
{
    PyRef r(PyObject_CallMethod(canon_, "get_external_length_units", nullptr));
    double v = r ? PyFloat_AsDouble(r.get()) : 1.0;
    if (!r || PyErr_Occurred()) {
        PyErr_Clear();
        return 1.0;
    }
    return v;
}

// machine length unit from get_external_length_units (about 1: mm, about 0.0394: inch)
CanonUnits PyCanon::get_external_length_unit_type()
{
    return get_external_length_units() > 0.5 ? CANON_UNITS_MM : CANON_UNITS_INCHES;
}
