/* hal_py_module.c: the _hal extension module: constants, exception and HAL attach. */
#include "hal_py.h"

PyObject *hal_py_error;

void hal_py_exit_all(void);

/* Integer constants of python.md §2. */
static const struct { const char *name; long value; } constants[] = {
    { "HAL_BIT", HAL_BIT }, { "HAL_FLOAT", HAL_FLOAT }, { "HAL_S32", HAL_S32 },
    { "HAL_U32", HAL_U32 }, { "HAL_PORT", HAL_PORT }, { "HAL_S64", HAL_S64 },
    { "HAL_U64", HAL_U64 }, { "HAL_BOOL", HAL_BIT }, { "HAL_REAL", HAL_FLOAT },
    { "HAL_SINT", HAL_S64 }, { "HAL_UINT", HAL_U64 },
    { "HAL_IN", HAL_IN }, { "HAL_OUT", HAL_OUT }, { "HAL_IO", HAL_IO },
    { "HAL_RO", HAL_RO }, { "HAL_RW", HAL_RW },
    { "MSG_NONE", 0 }, { "MSG_ERR", 1 }, { "MSG_WARN", 2 }, { "MSG_INFO", 3 },
    { "MSG_DBG", 4 }, { "MSG_ALL", 5 },
    { "is_kernelspace", 0 }, { "is_userspace", 1 },
    { "streamer_base", 0x48535430 }, { "sampler_base", 0x48534130 },
};

/* Detaches from HAL at interpreter exit, after removing our components. */
static void detach_at_exit(void)
{
    hal_py_exit_all();
    if (hal_is_init()) {
        hal_lib_exit();
    }
}

/* Adds every integer constant to the module. */
static int add_constants(PyObject *m)
{
    size_t n;
    for (n = 0; n < sizeof(constants) / sizeof(constants[0]); n++) {
        if (PyModule_AddIntConstant(m, constants[n].name, constants[n].value) < 0) {
            return -1;
        }
    }
    return PyModule_AddStringConstant(m, "kernel_version", "Not Available");
}

/* Adds the functions of one method table to the module. */
static int add_methods(PyObject *m, PyMethodDef *defs)
{
    return PyModule_AddFunctions(m, defs);
}

static struct PyModuleDef hal_py_module = {
    PyModuleDef_HEAD_INIT, "_hal", "Userspace HAL components and HAL access", -1,
    NULL, NULL, NULL, NULL, NULL,
};

/* Module init: attaches to HAL (hal.is_initialized() is True after import). */
PyMODINIT_FUNC PyInit__hal(void)
{
    PyObject *m;

    if (PyType_Ready(&hal_py_item_type) < 0 || PyType_Ready(&hal_py_stream_type) < 0) {
        return NULL;
    }
    m = PyModule_Create(&hal_py_module);
    if (m == NULL) {
        return NULL;
    }
    hal_py_error = PyErr_NewException("hal.error", PyExc_Exception, NULL);
    if (hal_py_error == NULL || PyModule_AddObjectRef(m, "error", hal_py_error) < 0
        || PyModule_AddObjectRef(m, "item", (PyObject *)&hal_py_item_type) < 0
        || PyModule_AddObjectRef(m, "stream", (PyObject *)&hal_py_stream_type) < 0
        || add_constants(m) < 0 || add_methods(m, hal_py_comp_methods) < 0
        || add_methods(m, hal_py_query_methods) < 0
        || add_methods(m, hal_py_signal_methods) < 0
        || add_methods(m, hal_py_introspect_methods) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    if (hal_lib_init() >= 0) {
        Py_AtExit(detach_at_exit);
    }
    return m;
}
