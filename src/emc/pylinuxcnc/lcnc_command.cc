// lcnc_command.cc: linuxcnc.command: write a command, wait for task's echo on the status sequence (no sleeping), wait_complete().
#include "lcnc_command.hh"

#include <time.h>

#include <cerrno>
#include <cstring>

namespace {

// Seconds task gets to read a command before a send gives up (silently, as LinuxCNC).
const double ECHO_TIMEOUT_S = 5.0;

// Monotonic seconds.
double now_s()
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

// Wrap-safe serial difference a - b.
int32_t serial_diff(int32_t a, int32_t b)
{
    return static_cast<int32_t>(static_cast<uint32_t>(a) - static_cast<uint32_t>(b));
}

// Sleep (without the GIL) until the status changes from seen or the deadline passes.
// 0 changed, -ETIMEDOUT, -ESHUTDOWN, or -1 with a Python exception (a signal handler raised).
int wait_status_change(PyCommand *c, uint32_t seen, double deadline)
{
    for (;;) {
        double left = deadline - now_s();
        if (left <= 0) return -ETIMEDOUT;
        int rc;
        Py_BEGIN_ALLOW_THREADS
        rc = nml_wait_change(c->stat->raw(), seen, static_cast<int64_t>(left * 1e9));
        Py_END_ALLOW_THREADS
        if (rc != -EINTR) return rc;
        if (PyErr_CheckSignals() < 0) return -1;
    }
}

// Wait until task has read serial (echo_serial_number - serial >= 0); -1 on a Python error.
int wait_echo(PyCommand *c, int32_t serial)
{
    double deadline = now_s() + ECHO_TIMEOUT_S;
    for (;;) {
        uint32_t seen = nml_change_count(c->stat->raw());
        int got = lcnc_peek_status(*c->stat, *c->scratch);
        if (got < 0) return -1;
        if (got > 0 && serial_diff(c->scratch->echo_serial_number, serial) >= 0) return 0;
        int rc = wait_status_change(c, seen, deadline);
        if (rc == -1) return -1;
        if (rc < 0) return 0; // timed out or the buffer went away: like LinuxCNC, no error
    }
}

// command(): links to emcCommand and emcStatus, attached lazily.
int command_init(PyObject *self, PyObject *args, PyObject *kw)
{
    PyCommand *c = reinterpret_cast<PyCommand *>(self);
    if (!PyArg_ParseTuple(args, ":command") || (kw && PyDict_Size(kw))) {
        if (!PyErr_Occurred()) PyErr_SetString(PyExc_TypeError, "command() takes no keyword arguments");
        return -1;
    }
    delete c->cmd;
    delete c->stat;
    delete c->scratch;
    c->cmd = new LcncLink("emcCommand");
    c->stat = new LcncLink("emcStatus");
    c->scratch = new EMC_STAT;
    c->serial = 0;
    return 0;
}

// Free the links.
void command_dealloc(PyObject *self)
{
    PyCommand *c = reinterpret_cast<PyCommand *>(self);
    PyTypeObject *type = Py_TYPE(self);
    delete c->cmd;
    delete c->stat;
    delete c->scratch;
    type->tp_free(self);
    Py_DECREF(type);
}

// wait_complete([timeout=5.0]): RCS_DONE / RCS_ERROR, or -1 on timeout. Only statuses
// written after the call count, so wait_complete(0) is always -1.
PyObject *command_wait_complete(PyObject *self, PyObject *args)
{
    PyCommand *c = reinterpret_cast<PyCommand *>(self);
    double timeout = 5.0;
    if (!PyArg_ParseTuple(args, "|d:wait_complete", &timeout)) return nullptr;
    if (!c->cmd || !c->stat->ready()) return PyLong_FromLong(-1);
    double deadline = now_s() + timeout;
    uint32_t seen = nml_change_count(c->stat->raw());
    for (;;) {
        int rc = wait_status_change(c, seen, deadline);
        if (rc == -1) return nullptr;
        if (rc < 0) return PyLong_FromLong(-1);
        seen = nml_change_count(c->stat->raw());
        int got = lcnc_peek_status(*c->stat, *c->scratch);
        if (got < 0) return nullptr;
        if (got == 0) continue;
        int32_t diff = serial_diff(c->scratch->echo_serial_number, c->serial);
        int status = c->scratch->status;
        if (diff > 0) return PyLong_FromLong(RCS_DONE);
        if (diff == 0 && (status == RCS_DONE || status == RCS_ERROR)) return PyLong_FromLong(status);
    }
}

// command.serial
PyObject *command_get_serial(PyObject *self, void *)
{
    return PyLong_FromLong(reinterpret_cast<PyCommand *>(self)->serial);
}

PyGetSetDef command_getsets[] = {
    {"serial", command_get_serial, nullptr, "serial of the last command this object sent", nullptr},
    {nullptr, nullptr, nullptr, nullptr, nullptr},
};

} // namespace

// Write a command and wait for task to read it.
PyObject *lcnc_command_send(PyObject *self, const NMLmsg &msg)
{
    PyCommand *c = reinterpret_cast<PyCommand *>(self);
    if (!c->cmd) {
        PyErr_SetString(lcnc_error, "command object was not initialised");
        return nullptr;
    }
    if (!c->cmd->ready() || !c->stat->ready()) Py_RETURN_NONE; // not running: nothing sent
    int32_t serial = 0;
    if (c->cmd->channel().write(msg, &serial) < 0) {
        PyErr_SetString(lcnc_error, c->cmd->channel().error().c_str());
        return nullptr;
    }
    c->serial = serial;
    if (wait_echo(c, serial) < 0) return nullptr;
    Py_RETURN_NONE;
}

// Create the command type (not subclassable) and add it.
int lcnc_add_command(PyObject *module)
{
    static std::vector<PyMethodDef> methods = lcnc_command_methods();
    methods.insert(methods.begin(), {"wait_complete", command_wait_complete, METH_VARARGS,
                                     "wait_complete([timeout]) -> RCS_DONE, RCS_ERROR or -1"});
    PyType_Slot slots[] = {
        {Py_tp_init, reinterpret_cast<void *>(command_init)},
        {Py_tp_dealloc, reinterpret_cast<void *>(command_dealloc)},
        {Py_tp_new, reinterpret_cast<void *>(PyType_GenericNew)},
        {Py_tp_methods, methods.data()},
        {Py_tp_getset, command_getsets},
        {Py_tp_doc, const_cast<char *>("command(): send commands to task")},
        {0, nullptr},
    };
    PyType_Spec spec = {"linuxcnc.command", sizeof(PyCommand), 0, Py_TPFLAGS_DEFAULT, slots};
    PyObject *type = PyType_FromSpec(&spec);
    if (!type) return -1;
    return PyModule_AddObject(module, "command", type) < 0 ? -1 : 0;
}
