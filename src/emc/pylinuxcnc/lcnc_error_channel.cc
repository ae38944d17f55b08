// lcnc_error_channel.cc: linuxcnc.error_channel: poll() takes the next operator message from emcError as (kind, text).
#include "lcnc_py.hh"

#include <cstring>
#include <vector>

namespace {

struct PyErrorChannel {
    PyObject_HEAD
    LcncLink *link;
};

// (kind, text) of a text message of class M with text field Field.
template <class M, auto Field>
PyObject *text_result(const NMLmsg *msg)
{
    const M *m = emc_msg_as<M>(msg);
    return Py_BuildValue("(iN)", msg->type, lcnc_text(m->*Field, sizeof(m->*Field)));
}

// The (kind, text) tuple of a message read from the buffer.
PyObject *message_tuple(const NMLmsg *msg, int len)
{
    std::string why;
    if (emc_msg_check(msg, static_cast<size_t>(len), &why) < 0 || !emc_msg_known(msg->type))
        return Py_BuildValue("(is)", msg->type, ("unrecognized error " + std::to_string(msg->type)).c_str());
    switch (msg->type) {
    case EMC_OPERATOR_ERROR_TYPE: return text_result<EMC_OPERATOR_ERROR, &EMC_OPERATOR_ERROR::error>(msg);
    case EMC_OPERATOR_TEXT_TYPE: return text_result<EMC_OPERATOR_TEXT, &EMC_OPERATOR_TEXT::text>(msg);
    case EMC_OPERATOR_DISPLAY_TYPE: return text_result<EMC_OPERATOR_DISPLAY, &EMC_OPERATOR_DISPLAY::display>(msg);
    case NML_ERROR_TYPE: return text_result<NML_ERROR, &NML_ERROR::error>(msg);
    case NML_TEXT_TYPE: return text_result<NML_TEXT, &NML_TEXT::text>(msg);
    case NML_DISPLAY_TYPE: return text_result<NML_DISPLAY, &NML_DISPLAY::display>(msg);
    default:
        return Py_BuildValue("(is)", msg->type, ("unrecognized error " + std::to_string(msg->type)).c_str());
    }
}

int error_init(PyObject *self, PyObject *args, PyObject *kw)
{
    PyErrorChannel *e = reinterpret_cast<PyErrorChannel *>(self);
    if (!PyArg_ParseTuple(args, ":error_channel") || (kw && PyDict_Size(kw))) {
        if (!PyErr_Occurred()) PyErr_SetString(PyExc_TypeError, "error_channel() takes no keyword arguments");
        return -1;
    }
    delete e->link;
    e->link = new LcncLink("emcError");
    return 0;
}

void error_dealloc(PyObject *self)
{
    PyTypeObject *type = Py_TYPE(self);
    delete reinterpret_cast<PyErrorChannel *>(self)->link;
    type->tp_free(self);
    Py_DECREF(type);
}

// poll() -> None or (kind, text). Removes the message for every reader of the system.
PyObject *error_poll(PyObject *self, PyObject *)
{
    PyErrorChannel *e = reinterpret_cast<PyErrorChannel *>(self);
    if (!e->link || !e->link->ready()) {
        PyErr_SetString(lcnc_error, "Error buffer invalid");
        return nullptr;
    }
    static std::vector<max_align_t> buf;
    size_t cap = nml_max_message(e->link->raw());
    buf.resize(cap / sizeof(max_align_t) + 1);
    int n = nml_read(e->link->raw(), buf.data(), cap);
    if (n == 0) Py_RETURN_NONE;
    if (n < 0) {
        PyErr_Format(lcnc_error, "Error buffer: %s", strerror(-n));
        return nullptr;
    }
    return message_tuple(reinterpret_cast<const NMLmsg *>(buf.data()), n);
}

PyMethodDef error_methods[] = {
    {"poll", error_poll, METH_NOARGS, "poll() -> None or (kind, text)"},
    {nullptr, nullptr, 0, nullptr},
};

} // namespace

int lcnc_add_error_channel(PyObject *module)
{
    PyType_Slot slots[] = {
        {Py_tp_init, reinterpret_cast<void *>(error_init)},
        {Py_tp_dealloc, reinterpret_cast<void *>(error_dealloc)},
        {Py_tp_new, reinterpret_cast<void *>(PyType_GenericNew)},
        {Py_tp_methods, error_methods},
        {Py_tp_doc, const_cast<char *>("error_channel(): operator messages from task")},
        {0, nullptr},
    };
    PyType_Spec spec = {"linuxcnc.error_channel", sizeof(PyErrorChannel), 0, Py_TPFLAGS_DEFAULT, slots};
    PyObject *type = PyType_FromSpec(&spec);
    if (!type) return -1;
    return PyModule_AddObject(module, "error_channel", type) < 0 ? -1 : 0;
}
