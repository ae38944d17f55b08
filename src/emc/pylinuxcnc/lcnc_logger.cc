// lcnc_logger.cc: linuxcnc.positionlogger: samples the tool position in a thread for the backplot, colour by motion type.
#include <dlfcn.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <vector>

#include "lcnc_preview.hh"

namespace {

// One vertex as OpenGL's GL_C4UB_V3F interleaved format wants it.
struct LogPoint {
    uint8_t color[4];
    float x, y, z;
};
static_assert(sizeof(LogPoint) == 16, "GL_C4UB_V3F records are 16 bytes");

// Points kept at most; the oldest half is dropped beyond.
const size_t MAX_POINTS = 200000;
const int N_COLORS = 6; // jog, traverse, feed, arc, toolchange, probe

// Everything the sampling thread and the Python methods share.
struct LoggerState {
    std::mutex lock;
    std::condition_variable wake;
    std::vector<LogPoint> points; // xyuv: pairs (xy point, uv point)
    uint8_t colors[N_COLORS][4] = {};
    std::string geometry;
    bool xyuv = false;
    bool running = false;
    bool stop = false;
    double depth_z = 0, depth_w = 0;
    LcncLink *link = nullptr;
};

struct PyLogger {
    PyObject_HEAD
    PyObject *stat;
    LoggerState *st;
};

// Colour index of a motion type.
int color_index(int motion_type)
{
    switch (motion_type) {
    case EMC_MOTION_TYPE_TRAVERSE: case EMC_MOTION_TYPE_INDEXROTARY: return 1;
    case EMC_MOTION_TYPE_FEED: return 2;
    case EMC_MOTION_TYPE_ARC: return 3;
    case EMC_MOTION_TYPE_TOOLCHANGE: return 4;
    case EMC_MOTION_TYPE_PROBING: return 5;
    default: return 0;
    }
}

// True when b lies on the segment direction a->c continued (same colour assumed).
bool collinear(const LogPoint &a, const LogPoint &b, const LogPoint &c)
{
    double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - b.x, c.y - b.y, c.z - b.z};
    double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    double nv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double ncross = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    return dot > 0 && ncross <= 1e-6 * nu * nv;
}

// Append one sample (1 or 2 vertices), merging straight runs of one colour.
void append(LoggerState &st, const LogPoint *sample, size_t per)
{
    std::lock_guard<std::mutex> g(st.lock);
    size_t n = st.points.size();
    if (n >= per && !memcmp(&st.points[n - per], sample, per * sizeof *sample)) return;
    if (n >= 2 * per && !memcmp(st.points[n - per].color, sample[0].color, 4) &&
        !memcmp(st.points[n - 2 * per].color, sample[0].color, 4) &&
        collinear(st.points[n - 2 * per], st.points[n - per], sample[0]) &&
        (per == 1 || collinear(st.points[n - 3], st.points[n - 1], sample[1]))) {
        memcpy(&st.points[n - per], sample, per * sizeof *sample);
        return;
    }
    if (n + per > MAX_POINTS) st.points.erase(st.points.begin(), st.points.begin() + (n / (2 * per)) * per);
    st.points.insert(st.points.end(), sample, sample + per);
}

// Turn a status into a sample: tool tip (feedback minus tool offset) through GEOMETRY.
void sample_of(LoggerState &st, const EMC_STAT &s)
{
    const EmcPose &p = s.motion.traj.actualPosition, &t = s.task.toolOffset;
    double pt9[9] = {p.tran.x - t.tran.x, p.tran.y - t.tran.y, p.tran.z - t.tran.z,
                     p.a - t.a, p.b - t.b, p.c - t.c, p.u - t.u, p.v - t.v, p.w - t.w};
    LogPoint out[2];
    const uint8_t *color = st.colors[color_index(s.motion.traj.motion_type)];
    size_t per = 1;
    if (st.xyuv) {
        out[0] = {{color[0], color[1], color[2], color[3]}, (float)pt9[0], (float)pt9[1], (float)st.depth_z};
        out[1] = {{color[0], color[1], color[2], color[3]}, (float)pt9[6], (float)pt9[7], (float)st.depth_w};
        per = 2;
    } else {
        double xyz[3];
        lcnc_vertex9(pt9, xyz, st.geometry.c_str());
        out[0] = {{color[0], color[1], color[2], color[3]}, (float)xyz[0], (float)xyz[1], (float)xyz[2]};
    }
    append(st, out, per);
}

// Parse six 4-tuples of 0..255 into colors.
bool parse_colors(PyObject *const *items, uint8_t colors[N_COLORS][4])
{
    for (int i = 0; i < N_COLORS; i++) {
        PyObject *args = PyTuple_Pack(1, items[i]);
        int ok = args && PyArg_ParseTuple(args, "(bbbb)", &colors[i][0], &colors[i][1],
                                          &colors[i][2], &colors[i][3]);
        Py_XDECREF(args);
        if (!ok) return false;
    }
    return true;
}

// positionlogger(stat, c_jog, c_traverse, c_feed, c_arc, c_toolchange, c_probe, geometry[, is_xyuv])
int logger_init(PyObject *self, PyObject *args, PyObject *)
{
    PyLogger *lg = reinterpret_cast<PyLogger *>(self);
    PyObject *stat = nullptr, *c[N_COLORS];
    const char *geometry = nullptr;
    int xyuv = 0;
    if (!PyArg_ParseTuple(args, "O!OOOOOOs|i:positionlogger", lcnc_stat_type, &stat, &c[0], &c[1],
                          &c[2], &c[3], &c[4], &c[5], &geometry, &xyuv))
        return -1;
    LoggerState *st = new LoggerState;
    if (!parse_colors(c, st->colors)) {
        delete st;
        return -1;
    }
    st->geometry = geometry;
    st->xyuv = xyuv != 0;
    st->link = new LcncLink("emcStatus");
    Py_XSETREF(lg->stat, Py_NewRef(stat));
    if (lg->st) {
        delete lg->st->link;
        delete lg->st;
    }
    lg->st = st;
    return 0;
}

void logger_dealloc(PyObject *self)
{
    PyLogger *lg = reinterpret_cast<PyLogger *>(self);
    PyTypeObject *type = Py_TYPE(self);
    if (lg->st) {
        delete lg->st->link;
        delete lg->st;
    }
    Py_XDECREF(lg->stat);
    type->tp_free(self);
    Py_DECREF(type);
}

// The state, or NULL with an exception for an uninitialised object.
LoggerState *state_of(PyObject *self)
{
    LoggerState *st = reinterpret_cast<PyLogger *>(self)->st;
    if (!st) PyErr_SetString(lcnc_error, "positionlogger was not initialised");
    return st;
}

// start(period_s): sample until stop() (blocks; run it in a thread).
PyObject *logger_start(PyObject *self, PyObject *args)
{
    double period = 0.01;
    LoggerState *st = state_of(self);
    if (!st || !PyArg_ParseTuple(args, "d:start", &period)) return nullptr;
    if (!(period > 0)) return PyErr_Format(PyExc_ValueError, "start: period must be > 0, not %g", period);
    {
        std::lock_guard<std::mutex> g(st->lock);
        if (st->running) return PyErr_Format(lcnc_error, "positionlogger is already running");
        st->running = true;
        st->stop = false;
    }
    EMC_STAT *status = new EMC_STAT;
    Py_BEGIN_ALLOW_THREADS
    std::unique_lock<std::mutex> g(st->lock);
    while (!st->stop) {
        g.unlock();
        if (st->link->ready() && nml_peek(st->link->raw(), status, sizeof *status) ==
                                     static_cast<int>(sizeof *status) &&
            status->type == EMC_STAT_TYPE)
            sample_of(*st, *status);
        g.lock();
        st->wake.wait_for(g, std::chrono::duration<double>(period), [st] { return st->stop; });
    }
    st->running = false;
    g.unlock();
    Py_END_ALLOW_THREADS
    delete status;
    Py_RETURN_NONE;
}

// stop(): end start()'s loop.
PyObject *logger_stop(PyObject *self, PyObject *)
{
    LoggerState *st = state_of(self);
    if (!st) return nullptr;
    {
        std::lock_guard<std::mutex> g(st->lock);
        st->stop = true;
    }
    st->wake.notify_all();
    Py_RETURN_NONE;
}

// clear(): forget every point.
PyObject *logger_clear(PyObject *self, PyObject *)
{
    LoggerState *st = state_of(self);
    if (!st) return nullptr;
    std::lock_guard<std::mutex> g(st->lock);
    st->points.clear();
    Py_RETURN_NONE;
}

// points() -> (bytes of GL_C4UB_V3F records, npts, is_xyuv)
PyObject *logger_points(PyObject *self, PyObject *)
{
    LoggerState *st = state_of(self);
    if (!st) return nullptr;
    std::lock_guard<std::mutex> g(st->lock);
    size_t per = st->xyuv ? 2 : 1;
    return Py_BuildValue("(y#nO)", reinterpret_cast<const char *>(st->points.data()),
                         static_cast<Py_ssize_t>(st->points.size() * sizeof(LogPoint)),
                         static_cast<Py_ssize_t>(st->points.size() / per), st->xyuv ? Py_True : Py_False);
}

// last([uvw]) -> most recent (x, y, z) (the uv point of an xyuv logger when uvw), or None.
PyObject *logger_last(PyObject *self, PyObject *args)
{
    int uvw = 0;
    LoggerState *st = state_of(self);
    if (!st || !PyArg_ParseTuple(args, "|i:last", &uvw)) return nullptr;
    std::lock_guard<std::mutex> g(st->lock);
    if (st->points.empty()) Py_RETURN_NONE;
    size_t i = st->points.size() - 1;
    if (st->xyuv && !uvw) i--;
    const LogPoint &p = st->points[i];
    return Py_BuildValue("(ddd)", (double)p.x, (double)p.y, (double)p.z);
}

// set_depth(z, w): depths at which an xyuv logger draws its XY and UV paths.
PyObject *logger_set_depth(PyObject *self, PyObject *args)
{
    LoggerState *st = state_of(self);
    double z = 0, w = 0;
    if (!st || !PyArg_ParseTuple(args, "dd:set_depth", &z, &w)) return nullptr;
    std::lock_guard<std::mutex> g(st->lock);
    st->depth_z = z;
    st->depth_w = w;
    Py_RETURN_NONE;
}

// set_colors(jog, traverse, feed, arc, toolchange, probe)
PyObject *logger_set_colors(PyObject *self, PyObject *args)
{
    LoggerState *st = state_of(self);
    PyObject *c[N_COLORS];
    uint8_t colors[N_COLORS][4];
    if (!st || !PyArg_ParseTuple(args, "OOOOOO:set_colors", &c[0], &c[1], &c[2], &c[3], &c[4], &c[5]) ||
        !parse_colors(c, colors))
        return nullptr;
    std::lock_guard<std::mutex> g(st->lock);
    memcpy(st->colors, colors, sizeof colors);
    Py_RETURN_NONE;
}

// get_colors() -> six (r, g, b, a) tuples.
PyObject *logger_get_colors(PyObject *self, PyObject *)
{
    LoggerState *st = state_of(self);
    if (!st) return nullptr;
    std::lock_guard<std::mutex> g(st->lock);
    PyObject *t = PyTuple_New(N_COLORS);
    for (int i = 0; t && i < N_COLORS; i++)
        PyTuple_SET_ITEM(t, i, Py_BuildValue("(iiii)", st->colors[i][0], st->colors[i][1],
                                             st->colors[i][2], st->colors[i][3]));
    return t;
}

// The OpenGL calls call() needs, from the libGL the GUI already loaded.
struct GlCalls {
    void (*enable_client)(unsigned);
    void (*disable_client)(unsigned);
    void (*vertex_pointer)(int, unsigned, int, const void *);
    void (*color_pointer)(int, unsigned, int, const void *);
    void (*draw_arrays)(unsigned, int, int);
};

// Resolve the GL calls; false when libGL is not loaded in this process.
bool gl_calls(GlCalls &gl)
{
    void *lib = dlopen("libGL.so.1", RTLD_LAZY | RTLD_NOLOAD);
    if (!lib) return false;
    gl.enable_client = reinterpret_cast<void (*)(unsigned)>(dlsym(lib, "glEnableClientState"));
    gl.disable_client = reinterpret_cast<void (*)(unsigned)>(dlsym(lib, "glDisableClientState"));
    gl.vertex_pointer = reinterpret_cast<void (*)(int, unsigned, int, const void *)>(dlsym(lib, "glVertexPointer"));
    gl.color_pointer = reinterpret_cast<void (*)(int, unsigned, int, const void *)>(dlsym(lib, "glColorPointer"));
    gl.draw_arrays = reinterpret_cast<void (*)(unsigned, int, int)>(dlsym(lib, "glDrawArrays"));
    dlclose(lib);
    return gl.enable_client && gl.disable_client && gl.vertex_pointer && gl.color_pointer && gl.draw_arrays;
}

// call(): draw the path as line strips in the current OpenGL context.
PyObject *logger_call(PyObject *self, PyObject *)
{
    enum : unsigned { GL_LINE_STRIP = 3, GL_UNSIGNED_BYTE = 0x1401, GL_FLOAT = 0x1406,
                      GL_VERTEX_ARRAY = 0x8074, GL_COLOR_ARRAY = 0x8076 };
    LoggerState *st = state_of(self);
    GlCalls gl;
    if (!st) return nullptr;
    if (!gl_calls(gl)) return PyErr_Format(lcnc_error, "positionlogger.call: OpenGL (libGL.so.1) is not loaded");
    std::lock_guard<std::mutex> g(st->lock);
    int per = st->xyuv ? 2 : 1, n = static_cast<int>(st->points.size()) / per;
    const uint8_t *base = reinterpret_cast<const uint8_t *>(st->points.data());
    gl.enable_client(GL_VERTEX_ARRAY);
    gl.enable_client(GL_COLOR_ARRAY);
    for (int k = 0; k < per && n > 0; k++) {
        gl.color_pointer(4, GL_UNSIGNED_BYTE, per * sizeof(LogPoint), base + k * sizeof(LogPoint));
        gl.vertex_pointer(3, GL_FLOAT, per * sizeof(LogPoint), base + k * sizeof(LogPoint) + 4);
        gl.draw_arrays(GL_LINE_STRIP, 0, n);
    }
    gl.disable_client(GL_COLOR_ARRAY);
    gl.disable_client(GL_VERTEX_ARRAY);
    Py_RETURN_NONE;
}

// npts: samples logged.
PyObject *logger_npts(PyObject *self, void *)
{
    LoggerState *st = state_of(self);
    if (!st) return nullptr;
    std::lock_guard<std::mutex> g(st->lock);
    return PyLong_FromSize_t(st->points.size() / (st->xyuv ? 2 : 1));
}

PyMethodDef logger_methods[] = {
    {"start", logger_start, METH_VARARGS, "start(period_s): sample until stop() (blocks)"},
    {"stop", logger_stop, METH_NOARGS, "stop(): end start()"},
    {"clear", logger_clear, METH_NOARGS, "clear(): forget the points"},
    {"call", logger_call, METH_NOARGS, "call(): draw the path with OpenGL"},
    {"points", logger_points, METH_NOARGS, "points() -> (GL_C4UB_V3F bytes, npts, is_xyuv)"},
    {"last", logger_last, METH_VARARGS, "last([uvw]) -> (x, y, z) or None"},
    {"set_depth", logger_set_depth, METH_VARARGS, "set_depth(z, w)"},
    {"set_colors", logger_set_colors, METH_VARARGS, "set_colors(jog, traverse, feed, arc, toolchange, probe)"},
    {"get_colors", logger_get_colors, METH_NOARGS, "get_colors() -> six colours"},
    {nullptr, nullptr, 0, nullptr},
};

PyGetSetDef logger_getsets[] = {
    {"npts", logger_npts, nullptr, "number of samples", nullptr},
    {nullptr, nullptr, nullptr, nullptr, nullptr},
};

} // namespace

int lcnc_add_logger(PyObject *module)
{
    PyType_Slot slots[] = {
        {Py_tp_init, reinterpret_cast<void *>(logger_init)},
        {Py_tp_dealloc, reinterpret_cast<void *>(logger_dealloc)},
        {Py_tp_new, reinterpret_cast<void *>(PyType_GenericNew)},
        {Py_tp_methods, logger_methods},
        {Py_tp_getset, logger_getsets},
        {Py_tp_doc, const_cast<char *>("positionlogger(stat, 6 colours, geometry[, is_xyuv]): backplot sampler")},
        {0, nullptr},
    };
    PyType_Spec spec = {"linuxcnc.positionlogger", sizeof(PyLogger), 0, Py_TPFLAGS_DEFAULT, slots};
    PyObject *type = PyType_FromSpec(&spec);
    if (!type) return -1;
    return PyModule_AddObject(module, "positionlogger", type) < 0 ? -1 : 0;
}
