/* hal_py_comp.c: _hal functions that create, ready and remove userspace components. */
#include "hal_py.h"
#include <string.h>

#define MAX_PY_COMPS 64

/* Components of this process still alive, removed at interpreter exit. */
static int live_comps[MAX_PY_COMPS];

/* Remembers or forgets a live component id. */
static void track(int comp_id, int alive)
{
    int n;
    for (n = 0; n < MAX_PY_COMPS; n++) {
        if (alive && live_comps[n] == 0) {
            live_comps[n] = comp_id;
            return;
        }
        if (!alive && live_comps[n] == comp_id) {
            live_comps[n] = 0;
            return;
        }
    }
}

/* Removes every component still alive (called by Py_AtExit). */
void hal_py_exit_all(void)
{
    int n;
    for (n = 0; n < MAX_PY_COMPS; n++) {
        if (live_comps[n] != 0) {
            hal_exit(live_comps[n]);
            live_comps[n] = 0;
        }
    }
}

/* Raises hal.error with strerror of a negative errno. */
PyObject *hal_py_raise_errno(int retval)
{
    PyErr_SetString(hal_py_error, strerror(-retval));
    return NULL;
}

/* init_component(name) -> id */
static PyObject *py_init_component(PyObject *self, PyObject *args)
{
    const char *name;
    int comp_id;

    (void)self;
    if (!PyArg_ParseTuple(args, "s:init_component", &name)) {
        return NULL;
    }
    if (strlen(name) > HAL_NAME_LEN) {
        return hal_py_raise_errno(-EINVAL);
    }
    comp_id = hal_init(name);
    if (comp_id < 0) {
        return hal_py_raise_errno(comp_id);
    }
    track(comp_id, 1);
    return PyLong_FromLong(comp_id);
}

/* Shared body of ready/unready/exit_component: applies fn to an id. */
static PyObject *apply_to_comp(PyObject *args, const char *fmt, int (*fn)(int), int forget)
{
    int comp_id, retval;

    if (!PyArg_ParseTuple(args, fmt, &comp_id)) {
        return NULL;
    }
    retval = fn(comp_id);
    if (forget) {
        track(comp_id, 0);
        if (!hal_is_init()) {
            hal_lib_init();  /* the library detaches with the last component; stay attached */
        }
    }
    if (retval < 0) {
        return hal_py_raise_errno(retval);
    }
    Py_RETURN_NONE;
}

/* ready(id) */
static PyObject *py_ready(PyObject *self, PyObject *args)
{
    (void)self;
    return apply_to_comp(args, "i:ready", hal_ready, 0);
}

/* unready(id) */
static PyObject *py_unready(PyObject *self, PyObject *args)
{
    (void)self;
    return apply_to_comp(args, "i:unready", hal_unready, 0);
}

/* exit_component(id) */
static PyObject *py_exit_component(PyObject *self, PyObject *args)
{
    (void)self;
    return apply_to_comp(args, "i:exit_component", hal_exit, 1);
}

/* new_item(comp_id, full_name, short_name, type, dir, is_pin) -> item */
static PyObject *py_new_item(PyObject *self, PyObject *args)
{
    const char *full, *short_name;
    int comp_id, type, dir, is_pin;

    (void)self;
    if (!PyArg_ParseTuple(args, "issiip:new_item", &comp_id, &full, &short_name,
                          &type, &dir, &is_pin)) {
        return NULL;
    }
    return hal_py_item_new(comp_id, full, short_name, type, dir, is_pin);
}

/* Looks a component up; 1 found, 0 not found. */
static int find_comp(PyObject *args, const char *fmt, hal_comp_info_t *info)
{
    const char *name;
    if (!PyArg_ParseTuple(args, fmt, &name)) {
        return -1;
    }
    return hal_comp_by_name(name, info) == 0 ? 1 : 0;
}

/* component_exists(name) -> bool */
static PyObject *py_component_exists(PyObject *self, PyObject *args)
{
    hal_comp_info_t info;
    int found = find_comp(args, "s:component_exists", &info);

    (void)self;
    if (found < 0) {
        return NULL;
    }
    return PyBool_FromLong(found);
}

/* component_is_ready(name) -> bool */
static PyObject *py_component_is_ready(PyObject *self, PyObject *args)
{
    hal_comp_info_t info;
    int found = find_comp(args, "s:component_is_ready", &info);

    (void)self;
    if (found < 0) {
        return NULL;
    }
    return PyBool_FromLong(found && info.ready);
}

PyMethodDef hal_py_comp_methods[] = {
    { "init_component", py_init_component, METH_VARARGS, "Create a userspace component" },
    { "ready", py_ready, METH_VARARGS, "Mark a component ready" },
    { "unready", py_unready, METH_VARARGS, "Mark a component not ready" },
    { "exit_component", py_exit_component, METH_VARARGS, "Remove a component" },
    { "new_item", py_new_item, METH_VARARGS, "Create a pin or param" },
    { "component_exists", py_component_exists, METH_VARARGS, "True if the component exists" },
    { "component_is_ready", py_component_is_ready, METH_VARARGS, "True if the component is ready" },
    { NULL, NULL, 0, NULL },
};
