/* hal_py_introspect.c: _hal._query(kind), raw descriptions of HAL objects for hal.query. */
#include "hal_py.h"
#include "hal_priv.h"
#include <string.h>

/* Python value of a cell; port handles give their buffer size. */
static PyObject *cell_value(hal_type_t type, hal_data_u *cell)
{
    if (type == HAL_PORT) {
        return PyLong_FromUnsignedLong(cell->p ? hal_port_buffer_size(&cell->p) : 0);
    }
    return hal_py_from_value(type, cell);
}

/* Describes one pin; mutex held. */
static PyObject *pin_dict(hal_pin_t *pin)
{
    hal_comp_t *owner = halpr_owner(pin->owner_ptr);
    hal_sig_t *sig = HALPR_AT(hal_sig_t, pin->signal);

    return Py_BuildValue("{s:s,s:z,s:i,s:i,s:N,s:z,s:s,s:i}", "name", pin->name,
        "original", pin->oldname ? halpr_original_name(pin->oldname) : NULL,
        "type", (int)pin->type, "dir", (int)pin->dir,
        "value", cell_value(pin->type, halpr_pin_value(pin)),
        "signal", sig ? sig->name : NULL, "comp", owner->name, "comp_id", owner->comp_id);
}

/* Describes one param; mutex held. */
static PyObject *param_dict(hal_param_t *param)
{
    hal_comp_t *owner = halpr_owner(param->owner_ptr);

    return Py_BuildValue("{s:s,s:z,s:i,s:i,s:N,s:s,s:i}", "name", param->name,
        "original", param->oldname ? halpr_original_name(param->oldname) : NULL,
        "type", (int)param->type, "dir", (int)param->dir,
        "value", cell_value(param->type, halpr_param_value(param)),
        "comp", owner->name, "comp_id", owner->comp_id);
}

/* Appends a pin name to a list; -1 on error. */
static int append_name(PyObject *list, const char *name)
{
    PyObject *text = PyUnicode_FromString(name);
    int rc = (text == NULL) ? -1 : PyList_Append(list, text);
    Py_XDECREF(text);
    return rc;
}

/* Describes one signal with its linked pins; the driver is the OUT pin, else an IO pin. */
static PyObject *sig_dict(hal_sig_t *sig)
{
    PyObject *pins = PyList_New(0);
    const char *out_pin = NULL, *io_pin = NULL;
    hal_pin_t *pin;

    if (pins == NULL) return NULL;
    for (pin = halpr_first_sig_pin(sig); pin != NULL; pin = halpr_next_sig_pin(pin)) {
        if (append_name(pins, pin->name) < 0) {
            Py_DECREF(pins);
            return NULL;
        }
        if (pin->dir == HAL_OUT) out_pin = pin->name;
        if (pin->dir == HAL_IO && io_pin == NULL) io_pin = pin->name;
    }
    return Py_BuildValue("{s:s,s:i,s:N,s:i,s:i,s:i,s:z,s:N}", "name", sig->name,
        "type", (int)sig->type, "value", cell_value(sig->type, halpr_sig_value(sig)),
        "writers", sig->writers, "readers", sig->readers, "bidirs", sig->bidirs,
        "driver", out_pin ? out_pin : io_pin, "pins", pins);
}

/* Describes one component; mutex held. */
static PyObject *comp_dict(hal_comp_t *comp)
{
    return Py_BuildValue("{s:s,s:i,s:i,s:i,s:O,s:z}", "name", comp->name,
        "type", comp->type, "id", comp->comp_id, "pid", comp->pid,
        "ready", comp->ready ? Py_True : Py_False, "insmod", halpr_insmod_args(comp));
}

/* Describes one function; mutex held. */
static PyObject *funct_dict(hal_funct_t *funct)
{
    hal_comp_t *owner = halpr_owner(funct->owner_ptr);

    return Py_BuildValue("{s:s,s:s,s:i,s:i,s:O}", "name", funct->name, "comp", owner->name,
        "comp_id", owner->comp_id, "users", funct->users,
        "reentrant", funct->reentrant ? Py_True : Py_False);
}

/* Appends (funct name, is_init) for every entry of a thread list; mutex held. */
static int add_entries(PyObject *list, int head, int is_init)
{
    hal_funct_entry_t *e;

    for (e = halpr_first_entry(head); e != NULL; e = halpr_next_entry(e)) {
        PyObject *item = Py_BuildValue("(sO)", halpr_entry_funct(e)->name,
                                       is_init ? Py_True : Py_False);
        if (item == NULL || PyList_Append(list, item) < 0) {
            Py_XDECREF(item);
            return -1;
        }
        Py_DECREF(item);
    }
    return 0;
}

/* Describes one thread with its functions in run order; mutex held. */
static PyObject *thread_dict(hal_thread_t *t)
{
    hal_comp_t *pseudo = HALPR_AT(hal_comp_t, t->comp_ptr);
    PyObject *functs = PyList_New(0);

    if (functs == NULL || add_entries(functs, t->funct_list, 0) < 0
        || (!t->init_done && add_entries(functs, t->init_list, 1) < 0)) {
        Py_XDECREF(functs);
        return NULL;
    }
    return Py_BuildValue("{s:s,s:z,s:i,s:i,s:l,s:N}", "name", t->name,
        "comp", pseudo ? pseudo->name : NULL, "comp_id", pseudo ? pseudo->comp_id : 0,
        "priority", t->priority, "period", t->period, "functions", functs);
}

/* Appends one description to the result list; -1 on error. */
static int append(PyObject *list, PyObject *item)
{
    int rc = (item == NULL) ? -1 : PyList_Append(list, item);
    Py_XDECREF(item);
    return rc;
}

/* Defines NAME(list): appends the dict of every object of one kind to list; mutex held. */
#define DEFINE_WALKER(NAME, TYPE, FIRST, NEXT, DICT)                  \
    static int NAME(PyObject *list)                                   \
    {                                                                 \
        int rc = 0;                                                   \
        for (TYPE *o = FIRST(); o && rc == 0; o = NEXT(o))            \
            rc = append(list, DICT(o));                               \
        return rc;                                                    \
    }

DEFINE_WALKER(walk_pins, hal_pin_t, halpr_first_pin, halpr_next_pin, pin_dict)
DEFINE_WALKER(walk_params, hal_param_t, halpr_first_param, halpr_next_param, param_dict)
DEFINE_WALKER(walk_signals, hal_sig_t, halpr_first_sig, halpr_next_sig, sig_dict)
DEFINE_WALKER(walk_comps, hal_comp_t, halpr_first_comp, halpr_next_comp, comp_dict)
DEFINE_WALKER(walk_functs, hal_funct_t, halpr_first_funct, halpr_next_funct, funct_dict)
DEFINE_WALKER(walk_threads, hal_thread_t, halpr_first_thread, halpr_next_thread, thread_dict)

/* Kind names and their walkers. */
static const struct { const char *kind; int (*walk)(PyObject *); } walkers[] = {
    { "pin", walk_pins }, { "param", walk_params }, { "signal", walk_signals },
    { "comp", walk_comps }, { "funct", walk_functs }, { "thread", walk_threads },
};

/* The walker of a kind, or NULL with ValueError set. */
static int (*find_walker(const char *kind))(PyObject *)
{
    size_t n;
    for (n = 0; n < sizeof(walkers) / sizeof(walkers[0]); n++) {
        if (strcmp(kind, walkers[n].kind) == 0) return walkers[n].walk;
    }
    PyErr_Format(PyExc_ValueError, "unknown HAL object kind '%s'", kind);
    return NULL;
}

/* _query(kind) -> list of dicts in HAL list order. */
static PyObject *py_query(PyObject *self, PyObject *args)
{
    const char *kind;
    PyObject *list;
    int rc;

    int (*walk)(PyObject *);

    (void)self;
    if (!PyArg_ParseTuple(args, "s:_query", &kind)) return NULL;
    walk = find_walker(kind);
    if (walk == NULL) return NULL;
    if (hal_data == NULL) return hal_py_raise_errno(-EFAULT);
    list = PyList_New(0);
    if (list == NULL) return NULL;
    halpr_mutex_get();
    rc = walk(list);
    halpr_mutex_give();
    if (rc < 0) {
        Py_DECREF(list);
        return NULL;
    }
    return list;
}

PyMethodDef hal_py_introspect_methods[] = {
    { "_query", py_query, METH_VARARGS, "Raw descriptions of HAL objects of one kind" },
    { NULL, NULL, 0, NULL },
};
