/* hal_py_value.c: conversions between Python objects and HAL value cells (python.md §2). */
#include "hal_py.h"
#include <strings.h>

/* Converts a text for a bit: named words, else int() of the text. */
static int text_to_bit(PyObject *obj, bool *out)
{
    static const char *const truthy[] = { "1", "true", "on", "yes" };
    static const char *const falsy[] = { "0", "false", "off", "no" };
    const char *text = PyUnicode_AsUTF8(obj);
    PyObject *num;
    size_t n;

    if (text == NULL) {
        return -1;
    }
    for (n = 0; n < 4; n++) {
        if (strcasecmp(text, truthy[n]) == 0) { *out = true; return 0; }
        if (strcasecmp(text, falsy[n]) == 0) { *out = false; return 0; }
    }
    num = PyLong_FromUnicodeObject(obj, 10);
    if (num == NULL) {
        return -1;
    }
    *out = PyObject_IsTrue(num) == 1;
    Py_DECREF(num);
    return 0;
}

/* Converts any accepted object to a bit value (non-zero floats are TRUE). */
static int to_bit(PyObject *obj, bool *out)
{
    PyObject *num;

    if (PyUnicode_Check(obj)) {
        return text_to_bit(obj, out);
    }
    if (PyFloat_Check(obj)) {
        *out = PyFloat_AsDouble(obj) != 0.0;
        return 0;
    }
    if (obj == Py_None) {
        PyErr_SetString(PyExc_TypeError, "Bit value expected, not NoneType");
        return -1;
    }
    num = PyNumber_Long(obj);
    if (num == NULL) {
        return -1;
    }
    *out = PyObject_IsTrue(num) == 1;
    Py_DECREF(num);
    return 0;
}

/* Converts numbers and numeric texts to a double. */
static int to_float(PyObject *obj, double *out)
{
    PyObject *num;

    if (PyFloat_Check(obj) || PyLong_Check(obj)) {
        *out = PyFloat_AsDouble(obj);
        return PyErr_Occurred() ? -1 : 0;
    }
    if (PyUnicode_Check(obj)) {
        num = PyFloat_FromString(obj);
        if (num != NULL) {
            *out = PyFloat_AsDouble(num);
            Py_DECREF(num);
            return 0;
        }
        PyErr_Clear();
    }
    PyErr_Format(PyExc_TypeError, "Number expected, not %s", Py_TYPE(obj)->tp_name);
    return -1;
}

/* Converts to an integer within [lo, hi]; OverflowError `Value V out of range`. */
static int to_ranged(PyObject *obj, long long lo, long long hi, long long *out)
{
    PyObject *num = PyNumber_Long(obj);
    int overflow = 0;
    long long v;

    if (num == NULL) {
        return -1;
    }
    v = PyLong_AsLongLongAndOverflow(num, &overflow);
    if (overflow != 0 || v < lo || v > hi) {
        PyErr_Format(PyExc_OverflowError, "Value %S out of range", num);
        Py_DECREF(num);
        return -1;
    }
    Py_DECREF(num);
    *out = v;
    return 0;
}

/* Converts to a 64-bit integer with Python's own overflow errors. */
static int to_wide(PyObject *obj, int is_signed, hal_data_u *out)
{
    PyObject *num = PyNumber_Long(obj);

    if (num == NULL) {
        return -1;
    }
    if (is_signed) {
        out->ls = PyLong_AsLongLong(num);
    } else {
        out->lu = PyLong_AsUnsignedLongLong(num);
    }
    Py_DECREF(num);
    return PyErr_Occurred() ? -1 : 0;
}

/* Converts a Python object into a value cell of the given HAL type. */
int hal_py_to_value(hal_type_t type, PyObject *obj, hal_data_u *out)
{
    long long v;
    bool bit;
    double real;

    switch (type) {
    case HAL_BIT:
        if (to_bit(obj, &bit) < 0) return -1;
        out->b = bit;
        return 0;
    case HAL_FLOAT:
        if (to_float(obj, &real) < 0) return -1;
        out->f = real;
        return 0;
    case HAL_S32:
        if (to_ranged(obj, INT32_MIN, INT32_MAX, &v) < 0) return -1;
        out->s = (int32_t)v;
        return 0;
    case HAL_U32:
        if (to_ranged(obj, 0, UINT32_MAX, &v) < 0) return -1;
        out->u = (uint32_t)v;
        return 0;
    case HAL_S64:
        return to_wide(obj, 1, out);
    case HAL_U64:
        return to_wide(obj, 0, out);
    default:
        PyErr_SetString(PyExc_RuntimeError, "not a valid HAL value type");
        return -1;
    }
}

/* Returns the Python object for a value cell. */
PyObject *hal_py_from_value(hal_type_t type, const void *value)
{
    switch (type) {
    case HAL_BIT: return PyBool_FromLong(*(const hal_bit_t *)value);
    case HAL_FLOAT: return PyFloat_FromDouble(*(const hal_float_t *)value);
    case HAL_S32: return PyLong_FromLong(*(const hal_s32_t *)value);
    case HAL_U32: return PyLong_FromUnsignedLong(*(const hal_u32_t *)value);
    case HAL_S64: return PyLong_FromLongLong(*(const hal_s64_t *)value);
    case HAL_U64: return PyLong_FromUnsignedLongLong(*(const hal_u64_t *)value);
    case HAL_PORT: return PyLong_FromUnsignedLong(*(const hal_u32_t *)value);
    default: Py_RETURN_NONE;
    }
}
