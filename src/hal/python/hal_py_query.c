/* hal_py_query.c: _hal functions on pins, params and signals by name (python.md §2). */
#include "hal_py.h"

/* Raises RuntimeError `<func>: <name>: <what>`; returns NULL. */
static PyObject *name_error(const char *func, const char *name, const char *what)
{
    PyErr_Format(PyExc_RuntimeError, "%s: %s: %s", func, name, what);
    return NULL;
}

/* new_sig(name, type) -> False on success, True on failure. */
static PyObject *py_new_sig(PyObject *self, PyObject *args)
{
    const char *name;
    int type;

    (void)self;
    if (!PyArg_ParseTuple(args, "si:new_sig", &name, &type)) {
        return NULL;
    }
    if (type < HAL_BIT || type > HAL_U64) {
        PyErr_SetString(PyExc_RuntimeError, "not a valid HAL signal type");
        return NULL;
    }
    return PyBool_FromLong(hal_signal_new(name, type) < 0);
}

/* connect(pin, sig) -> False on success, True on failure. */
static PyObject *py_connect(PyObject *self, PyObject *args)
{
    const char *pin, *sig;

    (void)self;
    if (!PyArg_ParseTuple(args, "ss:connect", &pin, &sig)) {
        return NULL;
    }
    return PyBool_FromLong(hal_link(pin, sig) < 0);
}

/* disconnect(pin) -> False on success, True on failure. */
static PyObject *py_disconnect(PyObject *self, PyObject *args)
{
    const char *pin;

    (void)self;
    if (!PyArg_ParseTuple(args, "s:disconnect", &pin)) {
        return NULL;
    }
    return PyBool_FromLong(hal_unlink(pin) < 0);
}

/* Shared body of set_p/set_s: convert by the object's type and write it. */
static PyObject *set_named(PyObject *args, const char *func, int is_signal)
{
    const char *name;
    PyObject *value;
    hal_type_t type;
    hal_data_u data = { 0 };
    int dir, writers, retval;

    if (!PyArg_ParseTuple(args, is_signal ? "sO:set_s" : "sO:set_p", &name, &value)) {
        return NULL;
    }
    retval = is_signal ? hal_get_s(name, &type, &data, &writers)
                       : hal_get_p(name, &type, &dir, &data);
    if (retval < 0) {
        return name_error(func, name, "not found");
    }
    if (hal_py_to_value(type == HAL_PORT ? HAL_U32 : type, value, &data) < 0) {
        PyErr_Clear();
        return name_error(func, name, "invalid argument");
    }
    retval = is_signal ? hal_set_s(name, type, &data) : hal_set_p(name, type, &data);
    if (retval == -EACCES) {
        return name_error(func, name, "not writable");
    }
    if (retval < 0) {
        return name_error(func, name, hal_strerror(retval));
    }
    Py_RETURN_TRUE;
}

/* set_p(name, value) -> True */
static PyObject *py_set_p(PyObject *self, PyObject *args)
{
    (void)self;
    return set_named(args, "set_p", 0);
}

/* set_s(name, value) -> True */
static PyObject *py_set_s(PyObject *self, PyObject *args)
{
    (void)self;
    return set_named(args, "set_s", 1);
}

/* Value of a pin or param, or NULL without exception when missing. */
static PyObject *lookup_p(const char *name)
{
    hal_type_t type;
    hal_data_u data;
    int dir;

    if (hal_get_p(name, &type, &dir, &data) < 0) {
        return NULL;
    }
    if (type == HAL_PORT) {
        return PyLong_FromUnsignedLong(data.p ? hal_port_buffer_size(&data.p) : 0);
    }
    return hal_py_from_value(type, &data);
}

/* Value of a signal, or NULL without exception when missing. */
static PyObject *lookup_s(const char *name)
{
    hal_type_t type;
    hal_data_u data;
    int writers;

    if (hal_get_s(name, &type, &data, &writers) < 0) {
        return NULL;
    }
    return hal_py_from_value(type, &data);
}

/* Parses one name with format fmt and returns lookup(name), or None when it is not found. */
static PyObject *get_or_none(PyObject *args, const char *fmt, PyObject *(*lookup)(const char *))
{
    const char *name;
    PyObject *value;

    if (!PyArg_ParseTuple(args, fmt, &name)) {
        return NULL;
    }
    value = lookup(name);
    if (value == NULL && !PyErr_Occurred()) {
        Py_RETURN_NONE;
    }
    return value;
}

/* get_p(name) -> value or None */
static PyObject *py_get_p(PyObject *self, PyObject *args)
{
    (void)self;
    return get_or_none(args, "s:get_p", lookup_p);
}

/* get_s(name) -> value or None */
static PyObject *py_get_s(PyObject *self, PyObject *args)
{
    (void)self;
    return get_or_none(args, "s:get_s", lookup_s);
}

/* get_value(name): pin, then param, then signal. */
static PyObject *py_get_value(PyObject *self, PyObject *args)
{
    const char *name;
    PyObject *value;

    (void)self;
    if (!PyArg_ParseTuple(args, "s:get_value", &name)) {
        return NULL;
    }
    value = lookup_p(name);
    if (value == NULL && !PyErr_Occurred()) {
        value = lookup_s(name);
    }
    if (value == NULL && !PyErr_Occurred()) {
        return name_error("get_value", name, "not found");
    }
    return value;
}

/* hal_list callback: appends {NAME, VALUE, DIRECTION, TYPE} to the list ctx. */
static int add_info(const char *name, hal_type_t type, int dir, void *ctx)
{
    PyObject *value = lookup_p(name);
    PyObject *dict;

    if (value == NULL) {
        PyErr_Clear();
        value = Py_None;
        Py_INCREF(value);
    }
    dict = Py_BuildValue("{s:s,s:N,s:i,s:i}", "NAME", name, "VALUE", value,
                         "DIRECTION", dir, "TYPE", (int)type);
    if (dict == NULL || PyList_Append((PyObject *)ctx, dict) < 0) {
        Py_XDECREF(dict);
        return 1;
    }
    Py_DECREF(dict);
    return 0;
}

/* Builds the info list of pins (walk = hal_list_p) or params (hal_list_p_s). */
static PyObject *info_list(int (*walk)(hal_list_cb_t, void *))
{
    PyObject *list = PyList_New(0);

    if (list == NULL) {
        return NULL;
    }
    walk(add_info, list);
    if (PyErr_Occurred()) {
        Py_DECREF(list);
        return NULL;
    }
    return list;
}

/* get_info_pins() */
static PyObject *py_get_info_pins(PyObject *self, PyObject *unused)
{
    (void)self;
    (void)unused;
    return info_list(hal_list_p);
}

/* get_info_params() */
static PyObject *py_get_info_params(PyObject *self, PyObject *unused)
{
    (void)self;
    (void)unused;
    return info_list(hal_list_p_s);
}

/* set_msg_level(level) */
static PyObject *py_set_msg_level(PyObject *self, PyObject *args)
{
    int level;

    (void)self;
    if (!PyArg_ParseTuple(args, "i:set_msg_level", &level)) {
        return NULL;
    }
    if (rtapi_set_msg_level(level) < 0) {
        PyErr_SetString(PyExc_RuntimeError, "set_msg_level failed");
        return NULL;
    }
    Py_RETURN_NONE;
}

/* get_msg_level() */
static PyObject *py_get_msg_level(PyObject *self, PyObject *unused)
{
    (void)self;
    (void)unused;
    return PyLong_FromLong(rtapi_get_msg_level());
}

/* get_realtime_type() as a plain int (hal.py wraps it in RTType). */
static PyObject *py_get_realtime_type(PyObject *self, PyObject *unused)
{
    (void)self;
    (void)unused;
    return PyLong_FromLong(hal_get_realtime_type());
}

/* is_initialized() */
static PyObject *py_is_initialized(PyObject *self, PyObject *unused)
{
    (void)self;
    (void)unused;
    return PyBool_FromLong(hal_is_init());
}

PyMethodDef hal_py_query_methods[] = {
    { "new_sig", py_new_sig, METH_VARARGS, "Create a signal; False on success" },
    { "connect", py_connect, METH_VARARGS, "Link a pin to a signal; False on success" },
    { "disconnect", py_disconnect, METH_VARARGS, "Unlink a pin; False on success" },
    { "set_p", py_set_p, METH_VARARGS, "Set a pin or param like setp" },
    { "set_s", py_set_s, METH_VARARGS, "Set a signal like sets" },
    { "get_p", py_get_p, METH_VARARGS, "Value of a pin or param, or None" },
    { "get_s", py_get_s, METH_VARARGS, "Value of a signal, or None" },
    { "get_value", py_get_value, METH_VARARGS, "Value of a pin, param or signal" },
    { "get_info_pins", py_get_info_pins, METH_NOARGS, "List of pin dicts" },
    { "get_info_params", py_get_info_params, METH_NOARGS, "List of param dicts" },
    { "set_msg_level", py_set_msg_level, METH_VARARGS, "Set the RTAPI message level" },
    { "get_msg_level", py_get_msg_level, METH_NOARGS, "RTAPI message level" },
    { "get_realtime_type", py_get_realtime_type, METH_NOARGS, "Realtime type number" },
    { "is_initialized", py_is_initialized, METH_NOARGS, "True when HAL is mapped" },
    { NULL, NULL, 0, NULL },
};
