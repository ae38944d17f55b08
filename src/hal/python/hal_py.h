/* hal_py.h: shared declarations of the _hal Python extension's C files. */
#ifndef HAL_PY_H
#define HAL_PY_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include "hal.h"

/* The _hal.error exception object. */
extern PyObject *hal_py_error;

/* The raw pin/param type `_hal.item`. */
extern PyTypeObject hal_py_item_type;

/* Converts a Python value for a HAL type; 0, or -1 with a Python exception set. */
int hal_py_to_value(hal_type_t type, PyObject *obj, hal_data_u *out);

/* Builds the Python value of a HAL value cell. */
PyObject *hal_py_from_value(hal_type_t type, const void *value);

/* Creates a pin or param owned by comp_id and returns a new `_hal.item`. */
PyObject *hal_py_item_new(int comp_id, const char *full_name, const char *short_name,
                          int type, int dir, int is_pin);

/* Sets hal.error from a negative errno. Always returns NULL. */
PyObject *hal_py_raise_errno(int retval);

/* Module functions about components (hal_py_comp.c). */
extern PyMethodDef hal_py_comp_methods[];

/* Module functions about pins, params and signals (hal_py_query.c). */
extern PyMethodDef hal_py_query_methods[];

/* Module functions that read signal internals (hal_py_signals.c). */
extern PyMethodDef hal_py_signal_methods[];

/* _hal._query (hal_py_introspect.c). */
extern PyMethodDef hal_py_introspect_methods[];

/* The `hal.stream` type (hal_py_stream.c). */
extern PyTypeObject hal_py_stream_type;

#endif
