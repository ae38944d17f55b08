/* hal_py_signals.c: _hal functions that need signal internals: pin_has_writer, get_info_signals. */
#include "hal_py.h"
#include "hal_priv.h"

/* Name of the OUT (else IO) pin driving a signal, or NULL; mutex held. */
static const char *signal_driver(hal_sig_t *sig)
{
    hal_pin_t *pin, *io_pin = NULL;

    for (pin = halpr_first_sig_pin(sig); pin != NULL; pin = halpr_next_sig_pin(pin)) {
        if (pin->dir == HAL_OUT) {
            return pin->name;
        }
        if (pin->dir == HAL_IO && io_pin == NULL) {
            io_pin = pin;
        }
    }
    return io_pin != NULL ? io_pin->name : NULL;
}

/* pin_has_writer(name): True when the pin's signal has an OUT or IO pin. */
static PyObject *py_pin_has_writer(PyObject *self, PyObject *args)
{
    const char *name;
    hal_pin_t *pin;
    int result = -1;

    (void)self;
    if (!PyArg_ParseTuple(args, "s:pin_has_writer", &name)) {
        return NULL;
    }
    if (hal_data == NULL) {
        return hal_py_raise_errno(-EFAULT);
    }
    halpr_mutex_get();
    pin = halpr_find_pin_by_name(name);
    if (pin != NULL) {
        hal_sig_t *sig = HALPR_AT(hal_sig_t, pin->signal);
        result = sig != NULL && (sig->writers > 0 || sig->bidirs > 0);
    }
    halpr_mutex_give();
    if (result < 0) {
        PyErr_Format(PyExc_NameError, "Pin `%s' does not exist", name);
        return NULL;
    }
    return PyBool_FromLong(result);
}

/* Builds the info dict of one signal; mutex held. */
static PyObject *signal_info(hal_sig_t *sig)
{
    const char *driver = signal_driver(sig);
    PyObject *value = hal_py_from_value(sig->type, halpr_sig_value(sig));

    if (value == NULL) {
        return NULL;
    }
    return Py_BuildValue("{s:s,s:N,s:z,s:i}", "NAME", sig->name, "VALUE", value,
                         "DRIVER", driver, "TYPE", (int)sig->type);
}

/* get_info_signals() -> list of {NAME, VALUE, DRIVER, TYPE}. */
static PyObject *py_get_info_signals(PyObject *self, PyObject *unused)
{
    PyObject *list, *dict;
    hal_sig_t *sig;

    (void)self;
    (void)unused;
    if (hal_data == NULL) {
        return hal_py_raise_errno(-EFAULT);
    }
    list = PyList_New(0);
    if (list == NULL) {
        return NULL;
    }
    halpr_mutex_get();
    for (sig = halpr_first_sig(); sig != NULL; sig = halpr_next_sig(sig)) {
        dict = signal_info(sig);
        if (dict == NULL || PyList_Append(list, dict) < 0) {
            Py_XDECREF(dict);
            Py_CLEAR(list);
            break;
        }
        Py_DECREF(dict);
    }
    halpr_mutex_give();
    return list;
}

PyMethodDef hal_py_signal_methods[] = {
    { "pin_has_writer", py_pin_has_writer, METH_VARARGS, "True if the pin's signal has a writer" },
    { "get_info_signals", py_get_info_signals, METH_NOARGS, "List of signal dicts" },
    { NULL, NULL, 0, NULL },
};
