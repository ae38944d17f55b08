/* hal_py_stream.c: `hal.stream`, Python access to sampler/streamer record FIFOs (python.md §2). */
#include "hal_py.h"

/* A created or attached stream. */
typedef struct {
    PyObject_HEAD
    hal_stream_t stream;
    int key;
    int creator;
    int open;
    unsigned sampleno;
} hal_py_stream_t;

/* Letters of the element types, indexed by hal_type_t. */
static const char type_letters[] = "?bfsu?lk";

/* Gets the component id from a hal.component (its _id) or an int. */
static int comp_id_of(PyObject *comp)
{
    PyObject *id = PyObject_HasAttrString(comp, "_id") ? PyObject_GetAttrString(comp, "_id")
                                                      : (Py_INCREF(comp), comp);
    long value;

    if (id == NULL) {
        return -1;
    }
    value = PyLong_AsLong(id);
    Py_DECREF(id);
    return (int)value;
}

/* stream(comp, key, depth, typestr) creates; stream(comp, key[, typestr]) attaches. */
static int stream_init(PyObject *obj, PyObject *args, PyObject *kwds)
{
    hal_py_stream_t *self = (hal_py_stream_t *)obj;
    PyObject *comp, *third = NULL;
    const char *types = NULL;
    int comp_id, retval;

    (void)kwds;
    if (!PyArg_ParseTuple(args, "Oi|Oz:stream", &comp, &self->key, &third, &types)) {
        return -1;
    }
    comp_id = comp_id_of(comp);
    if (comp_id < 0 && PyErr_Occurred()) {
        return -1;
    }
    self->creator = third != NULL && PyLong_Check(third);
    if (self->creator) {
        retval = hal_stream_create(&self->stream, comp_id, self->key,
                                   (int)PyLong_AsLong(third), types);
    } else {
        if (third != NULL && third != Py_None && !PyUnicode_Check(third)) {
            PyErr_SetString(PyExc_TypeError, "stream: depth must be an int, typestr a str");
            return -1;
        }
        types = (third != NULL && third != Py_None) ? PyUnicode_AsUTF8(third) : NULL;
        retval = hal_stream_attach(&self->stream, comp_id, self->key, types);
    }
    if (retval < 0) {
        hal_py_raise_errno(retval);
        return -1;
    }
    self->open = 1;
    return 0;
}

/* Releases the stream: creators destroy it, readers/writers detach. */
static void stream_dealloc(PyObject *obj)
{
    hal_py_stream_t *self = (hal_py_stream_t *)obj;

    if (self->open) {
        if (self->creator) {
            hal_stream_destroy(&self->stream);
        } else {
            hal_stream_detach(&self->stream);
        }
    }
    Py_TYPE(obj)->tp_free(obj);
}

/* Refuses use of a stream whose set-up failed. */
static int check_open(hal_py_stream_t *self)
{
    if (!self->open) {
        PyErr_SetString(PyExc_RuntimeError, "stream is not open");
        return -1;
    }
    return 0;
}

/* read() -> tuple of values, or None when the FIFO is empty. */
static PyObject *stream_read(PyObject *obj, PyObject *unused)
{
    hal_py_stream_t *self = (hal_py_stream_t *)obj;
    union hal_stream_data rec[HAL_STREAM_MAX_PINS];
    hal_data_u cell;
    PyObject *tuple;
    int n, count;

    (void)unused;
    if (check_open(self) < 0) return NULL;
    if (hal_stream_read(&self->stream, rec, &self->sampleno) < 0) {
        Py_RETURN_NONE;
    }
    count = hal_stream_element_count(&self->stream);
    tuple = PyTuple_New(count);
    for (n = 0; tuple != NULL && n < count; n++) {
        hal_type_t type = hal_stream_element_type(&self->stream, n);
        memset(&cell, 0, sizeof(cell));
        switch (type) {
        case HAL_BIT: cell.b = rec[n].b; break;
        case HAL_FLOAT: cell.f = rec[n].f; break;
        case HAL_S32: cell.s = rec[n].s; break;
        case HAL_U32: cell.u = rec[n].u; break;
        case HAL_S64: cell.ls = rec[n].l; break;
        default: cell.lu = rec[n].k; break;
        }
        PyTuple_SET_ITEM(tuple, n, hal_py_from_value(type, &cell));
    }
    return tuple;
}

/* Converts one Python value into record field n. */
static int field_from_py(hal_py_stream_t *self, int n, PyObject *item, union hal_stream_data *f)
{
    hal_type_t type = hal_stream_element_type(&self->stream, n);
    hal_data_u cell = { 0 };

    if (hal_py_to_value(type, item, &cell) < 0) return -1;
    switch (type) {
    case HAL_BIT: f->b = cell.b; break;
    case HAL_FLOAT: f->f = cell.f; break;
    case HAL_S32: f->s = cell.s; break;
    case HAL_U32: f->u = cell.u; break;
    case HAL_S64: f->l = cell.ls; break;
    default: f->k = cell.lu; break;
    }
    return 0;
}

/* write(tuple) -> None; IOError when full, ValueError on a wrong length. */
static PyObject *stream_write(PyObject *obj, PyObject *values)
{
    hal_py_stream_t *self = (hal_py_stream_t *)obj;
    union hal_stream_data rec[HAL_STREAM_MAX_PINS];
    PyObject *seq;
    Py_ssize_t n, count;

    if (check_open(self) < 0) return NULL;
    seq = PySequence_Fast(values, "stream.write: a sequence of values is required");
    if (seq == NULL) return NULL;
    count = hal_stream_element_count(&self->stream);
    if (PySequence_Fast_GET_SIZE(seq) != count) {
        PyErr_SetString(PyExc_ValueError, PySequence_Fast_GET_SIZE(seq) < count
                        ? "Too few elements to unpack" : "Too many elements to unpack");
        Py_DECREF(seq);
        return NULL;
    }
    for (n = 0; n < count; n++) {
        if (field_from_py(self, (int)n, PySequence_Fast_GET_ITEM(seq, n), &rec[n]) < 0) {
            Py_DECREF(seq);
            return NULL;
        }
    }
    Py_DECREF(seq);
    if (hal_stream_write(&self->stream, rec) < 0) {
        PyErr_SetString(PyExc_IOError, "stream is full");
        return NULL;
    }
    Py_RETURN_NONE;
}

/* Shared getter body: an int property computed by fn. */
static PyObject *int_prop(PyObject *obj, int (*fn)(hal_stream_t *))
{
    hal_py_stream_t *self = (hal_py_stream_t *)obj;
    if (check_open(self) < 0) return NULL;
    return PyLong_FromLong(fn(&self->stream));
}

/* Property getters. */
static PyObject *get_depth(PyObject *o, void *c) { (void)c; return int_prop(o, hal_stream_depth); }
static PyObject *get_maxdepth(PyObject *o, void *c) { (void)c; return int_prop(o, hal_stream_maxdepth); }
static PyObject *get_underruns(PyObject *o, void *c) { (void)c; return int_prop(o, hal_stream_num_underruns); }
static PyObject *get_overruns(PyObject *o, void *c) { (void)c; return int_prop(o, hal_stream_num_overruns); }

/* stream.readable: a record is waiting. */
static PyObject *get_readable(PyObject *o, void *c)
{
    (void)c;
    if (check_open((hal_py_stream_t *)o) < 0) return NULL;
    return PyBool_FromLong(hal_stream_readable(&((hal_py_stream_t *)o)->stream));
}
/* stream.writable: a record fits now. */
static PyObject *get_writable(PyObject *o, void *c)
{
    (void)c;
    if (check_open((hal_py_stream_t *)o) < 0) return NULL;
    return PyBool_FromLong(hal_stream_writable(&((hal_py_stream_t *)o)->stream));
}

/* element_types: bytes of type letters, e.g. b'fbsulk'. */
static PyObject *get_element_types(PyObject *obj, void *c)
{
    hal_py_stream_t *self = (hal_py_stream_t *)obj;
    char letters[HAL_STREAM_MAX_PINS + 1];
    int n, count;

    (void)c;
    if (check_open(self) < 0) return NULL;
    count = hal_stream_element_count(&self->stream);
    for (n = 0; n < count && n < HAL_STREAM_MAX_PINS; n++) {
        int type = hal_stream_element_type(&self->stream, n);
        letters[n] = (type >= 0 && type <= 7) ? type_letters[type] : '?';
    }
    return PyBytes_FromStringAndSize(letters, n);
}

/* sampleno: sample number of the last record read. */
static PyObject *get_sampleno(PyObject *obj, void *c)
{
    (void)c;
    return PyLong_FromUnsignedLong(((hal_py_stream_t *)obj)->sampleno);
}

/* repr: `<stream 0x48535430 creator>` or `... user>`. */
static PyObject *stream_repr(PyObject *obj)
{
    hal_py_stream_t *self = (hal_py_stream_t *)obj;
    char text[64];
    snprintf(text, sizeof(text), "<stream 0x%08x %s>", (unsigned)self->key,
             self->creator ? "creator" : "user");
    return PyUnicode_FromString(text);
}

static PyMethodDef stream_methods[] = {
    { "read", stream_read, METH_NOARGS, "Next record as a tuple, or None" },
    { "write", stream_write, METH_O, "Append a record (tuple)" },
    { NULL, NULL, 0, NULL },
};

static PyGetSetDef stream_getset[] = {
    { "readable", get_readable, NULL, "A record can be read", NULL },
    { "writable", get_writable, NULL, "A record can be written", NULL },
    { "depth", get_depth, NULL, "Records in the FIFO", NULL },
    { "maxdepth", get_maxdepth, NULL, "Depth given at creation", NULL },
    { "num_underruns", get_underruns, NULL, "Reads from an empty FIFO", NULL },
    { "num_overruns", get_overruns, NULL, "Writes to a full FIFO", NULL },
    { "element_types", get_element_types, NULL, "Type letters", NULL },
    { "sampleno", get_sampleno, NULL, "Sample number of the last read", NULL },
    { NULL, NULL, NULL, NULL, NULL },
};

PyTypeObject hal_py_stream_type = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "hal.stream",
    .tp_basicsize = sizeof(hal_py_stream_t),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "stream(comp, key, depth, typestr) creates, stream(comp, key[, typestr]) attaches",
    .tp_new = PyType_GenericNew,
    .tp_init = stream_init,
    .tp_dealloc = stream_dealloc,
    .tp_repr = stream_repr,
    .tp_methods = stream_methods,
    .tp_getset = stream_getset,
};
