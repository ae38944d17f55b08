/* hal_py_item.c: `_hal.item`, a raw pin or param of a Python-owned component. */
#include "hal_py.h"
#include <stdio.h>

/* One pin or param: pins hold a HAL-memory pointer cell, params their value cell. */
typedef struct {
    PyObject_HEAD
    int is_pin;
    hal_type_t type;
    int dir;
    void *storage;   /* pin: hal_data_u ** cell; param: hal_data_u cell */
    char name[HAL_NAME_LEN + 1];
} hal_py_item_t;

/* Returns the value cell the item currently reads and writes. */
static hal_data_u *item_cell(hal_py_item_t *self)
{
    if (self->is_pin) {
        return *(hal_data_u **)self->storage;
    }
    return (hal_data_u *)self->storage;
}

/* Creates the HAL object and wraps it. */
PyObject *hal_py_item_new(int comp_id, const char *full_name, const char *short_name,
                          int type, int dir, int is_pin)
{
    hal_py_item_t *self;
    int retval;
    void *storage = hal_malloc(is_pin ? (long)sizeof(void *) : 8);

    if (storage == NULL) {
        return hal_py_raise_errno(-ENOMEM);
    }
    if (is_pin) {
        retval = hal_pin_new(full_name, type, dir, (void **)storage, comp_id);
    } else {
        retval = hal_param_new(full_name, type, dir, storage, comp_id);
    }
    if (retval < 0) {
        return hal_py_raise_errno(retval);
    }
    self = PyObject_New(hal_py_item_t, &hal_py_item_type);
    if (self == NULL) {
        return NULL;
    }
    self->is_pin = is_pin;
    self->type = type;
    self->dir = dir;
    self->storage = storage;
    snprintf(self->name, sizeof(self->name), "%s", short_name);
    return (PyObject *)self;
}

/* item.get(): current value (port pins: buffer size). */
static PyObject *item_get(PyObject *obj, PyObject *unused)
{
    hal_py_item_t *self = (hal_py_item_t *)obj;
    hal_data_u *cell = item_cell(self);

    (void)unused;
    if (self->type == HAL_PORT) {
        return PyLong_FromUnsignedLong(cell->p ? hal_port_buffer_size(&cell->p) : 0);
    }
    return hal_py_from_value(self->type, cell);
}

/* item.set(v): writes v (converted per python.md) and returns v's stored value. */
static PyObject *item_set(PyObject *obj, PyObject *value)
{
    hal_py_item_t *self = (hal_py_item_t *)obj;
    hal_data_u tmp = { 0 };
    hal_data_u *cell = item_cell(self);

    if (self->type == HAL_PORT) {
        PyErr_SetString(PyExc_RuntimeError, "cannot set the value of a port pin");
        return NULL;
    }
    if (hal_py_to_value(self->type, value, &tmp) < 0) {
        return NULL;
    }
    switch (self->type) {  /* typed stores: a param cell is aligned only for its own type */
    case HAL_BIT: *(hal_bit_t *)(void *)cell = tmp.b; break;
    case HAL_FLOAT: *(hal_float_t *)(void *)cell = tmp.f; break;
    case HAL_S32: *(hal_s32_t *)(void *)cell = tmp.s; break;
    case HAL_U32: *(hal_u32_t *)(void *)cell = tmp.u; break;
    case HAL_S64: *(hal_s64_t *)(void *)cell = tmp.ls; break;
    default: *(hal_u64_t *)(void *)cell = tmp.lu; break;
    }
    Py_RETURN_NONE;
}

/* Port handle of a port pin with the given direction; 0 (exception set) otherwise. */
static int item_port(hal_py_item_t *self, const char *op, int dir)
{
    if (!self->is_pin || self->type != HAL_PORT) {
        PyErr_Format(PyExc_RuntimeError, "%s: %s: Pin not a port", op, self->name);
        return 0;
    }
    if (dir != 0 && self->dir != dir) {
        PyErr_Format(PyExc_RuntimeError, "%s: %s: Pin not %s", op, self->name,
                     dir == HAL_OUT ? "output" : "input");
        return 0;
    }
    if (item_cell(self)->p == 0) {
        PyErr_Format(PyExc_RuntimeError, "%s: %s: port has no buffer", op, self->name);
    }
    return item_cell(self)->p;
}

/* item.write(bytes|str) -> True when all bytes fit (OUT ports). */
static PyObject *item_port_write(PyObject *obj, PyObject *data)
{
    hal_port_t port = item_port((hal_py_item_t *)obj, "write", HAL_OUT);
    const char *bytes;
    Py_ssize_t len;

    if (port == 0) return NULL;
    if (PyUnicode_Check(data)) {
        bytes = PyUnicode_AsUTF8AndSize(data, &len);
    } else if (PyBytes_AsStringAndSize(data, (char **)&bytes, &len) < 0) {
        bytes = NULL;
    }
    if (bytes == NULL) return NULL;
    return PyBool_FromLong(hal_port_write(&port, bytes, (unsigned)len));
}

/* Shared body of read/peek: count bytes as bytes, or False when not available. */
static PyObject *port_take(PyObject *obj, PyObject *args, const char *op, int consume)
{
    hal_port_t port = item_port((hal_py_item_t *)obj, op, HAL_IN);
    unsigned count;
    PyObject *out;
    bool ok;

    if (port == 0 || !PyArg_ParseTuple(args, "I", &count)) return NULL;
    out = PyBytes_FromStringAndSize(NULL, count);
    if (out == NULL) return NULL;
    ok = consume ? hal_port_read(&port, PyBytes_AS_STRING(out), count)
                 : hal_port_peek(&port, PyBytes_AS_STRING(out), count);
    if (!ok) {
        Py_DECREF(out);
        Py_RETURN_FALSE;
    }
    return out;
}

/* item.read(n) */
static PyObject *item_port_read(PyObject *obj, PyObject *args)
{
    return port_take(obj, args, "read", 1);
}

/* item.peek(n) */
static PyObject *item_port_peek(PyObject *obj, PyObject *args)
{
    return port_take(obj, args, "peek", 0);
}

/* item.peek_commit(n) -> bool: drops n peeked bytes. */
static PyObject *item_port_peek_commit(PyObject *obj, PyObject *args)
{
    hal_port_t port = item_port((hal_py_item_t *)obj, "peek_commit", HAL_IN);
    unsigned count;

    if (port == 0 || !PyArg_ParseTuple(args, "I", &count)) return NULL;
    return PyBool_FromLong(hal_port_peek_commit(&port, count));
}

/* item.clear(): empties the port. */
static PyObject *item_port_clear(PyObject *obj, PyObject *unused)
{
    hal_port_t port = item_port((hal_py_item_t *)obj, "clear", 0);

    (void)unused;
    if (port == 0) return NULL;
    hal_port_clear(&port);
    Py_RETURN_NONE;
}

/* Shared body of size/readable/writable: an unsigned port figure. */
static PyObject *port_figure(PyObject *obj, const char *op, unsigned (*fn)(const hal_port_t *))
{
    hal_port_t port = item_port((hal_py_item_t *)obj, op, 0);
    if (port == 0) return NULL;
    return PyLong_FromUnsignedLong(fn(&port));
}

/* item.size(): a port's buffer size in bytes. */
static PyObject *item_port_size(PyObject *obj, PyObject *unused)
{
    (void)unused;
    return port_figure(obj, "size", hal_port_buffer_size);
}
/* item.readable(): bytes a port holds for reading. */
static PyObject *item_port_readable(PyObject *obj, PyObject *unused)
{
    (void)unused;
    return port_figure(obj, "readable", hal_port_readable);
}
/* item.writable(): bytes a port can take. */
static PyObject *item_port_writable(PyObject *obj, PyObject *unused)
{
    (void)unused;
    return port_figure(obj, "writable", hal_port_writable);
}

/* item.get_type() */
static PyObject *item_get_type(PyObject *obj, PyObject *unused)
{
    (void)unused;
    return PyLong_FromLong(((hal_py_item_t *)obj)->type);
}

/* item.get_dir() */
static PyObject *item_get_dir(PyObject *obj, PyObject *unused)
{
    (void)unused;
    return PyLong_FromLong(((hal_py_item_t *)obj)->dir);
}

/* item.get_name(): the short name, without prefix. */
static PyObject *item_get_name(PyObject *obj, PyObject *unused)
{
    (void)unused;
    return PyUnicode_FromString(((hal_py_item_t *)obj)->name);
}

/* item.is_pin() */
static PyObject *item_is_pin(PyObject *obj, PyObject *unused)
{
    (void)unused;
    return PyBool_FromLong(((hal_py_item_t *)obj)->is_pin);
}

/* Text of a HAL type for repr. */
static const char *type_text(hal_type_t type)
{
    static const char *const names[] = { "?", "BIT", "FLOAT", "S32", "U32", "PORT", "S64", "U64" };
    return (type >= 1 && type <= 7) ? names[type] : "?";
}

/* Text of a direction for repr. */
static const char *dir_text(int dir)
{
    switch (dir) {
    case HAL_IN: return "IN";
    case HAL_OUT: return "OUT";
    case HAL_IO: return "IO";
    case HAL_RO: return "RO";
    case HAL_RW: return "RW";
    default: return "?";
    }
}

/* repr: `<hal pin "x" BIT-IN>` / `<hal param "p" FLOAT-RW>`. */
static PyObject *item_repr(PyObject *obj)
{
    hal_py_item_t *self = (hal_py_item_t *)obj;
    return PyUnicode_FromFormat("<hal %s \"%s\" %s-%s>", self->is_pin ? "pin" : "param",
                                self->name, type_text(self->type), dir_text(self->dir));
}

static PyMethodDef item_methods[] = {
    { "get", item_get, METH_NOARGS, "Current value" },
    { "set", item_set, METH_O, "Write a value" },
    { "get_type", item_get_type, METH_NOARGS, "HAL type (int)" },
    { "get_dir", item_get_dir, METH_NOARGS, "HAL direction (int)" },
    { "get_name", item_get_name, METH_NOARGS, "Short name" },
    { "is_pin", item_is_pin, METH_NOARGS, "True for pins" },
    { "write", item_port_write, METH_O, "Port: write bytes; True when they fit" },
    { "read", item_port_read, METH_VARARGS, "Port: read n bytes, or False" },
    { "peek", item_port_peek, METH_VARARGS, "Port: look at n bytes, or False" },
    { "peek_commit", item_port_peek_commit, METH_VARARGS, "Port: drop n peeked bytes" },
    { "clear", item_port_clear, METH_NOARGS, "Port: drop all bytes" },
    { "size", item_port_size, METH_NOARGS, "Port: buffer size" },
    { "readable", item_port_readable, METH_NOARGS, "Port: bytes readable" },
    { "writable", item_port_writable, METH_NOARGS, "Port: bytes writable" },
    { NULL, NULL, 0, NULL },
};

PyTypeObject hal_py_item_type = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "hal.item",
    .tp_basicsize = sizeof(hal_py_item_t),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A pin or param of a userspace HAL component",
    .tp_repr = item_repr,
    .tp_methods = item_methods,
};
