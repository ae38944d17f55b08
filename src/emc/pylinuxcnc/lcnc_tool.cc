// lcnc_tool.cc: stat.tool_table and stat.toolinfo() from the tool-data segment task publishes.
#include "lcnc_py.hh"

#include <vector>

PyTypeObject *lcnc_tool_type = nullptr;

namespace {

// The process's tool-data attachment (made by the first poll of any stat object).
tooldata_t *tool_data = nullptr;
bool tool_attach_tried = false;
// Cached copy of the table and its generation.
std::vector<tooldata_entry_t> tool_cache;
uint64_t tool_cache_generation = 0;

PyStructSequence_Field tool_fields[] = {
    {"id", "tool number"},
    {"xoffset", nullptr}, {"yoffset", nullptr}, {"zoffset", nullptr},
    {"aoffset", nullptr}, {"boffset", nullptr}, {"coffset", nullptr},
    {"uoffset", nullptr}, {"voffset", nullptr}, {"woffset", nullptr},
    {"diameter", nullptr}, {"frontangle", nullptr}, {"backangle", nullptr},
    {"orientation", nullptr},
    {nullptr, nullptr},
};

PyStructSequence_Desc tool_desc = {"linuxcnc.tool_result", "one tool-table row", tool_fields, 14};

// Refresh the cached table when the generation changed; false when not attached.
bool refresh_cache()
{
    if (tool_data && !tooldata_alive(tool_data)) {
        tooldata_close(tool_data);
        tool_data = nullptr;
        tool_cache.clear();
    }
    if (!tool_data) {
        lcnc_tool_attach();
        if (!tool_data) return false;
    }
    uint64_t gen = tooldata_generation(tool_data);
    if (gen == tool_cache_generation && !tool_cache.empty()) return true;
    tool_cache.resize(TOOLDATA_MAX_ENTRIES);
    int n = tooldata_read(tool_data, tool_cache.data(), TOOLDATA_MAX_ENTRIES, &gen);
    tool_cache.resize(n > 0 ? static_cast<size_t>(n) : 0);
    tool_cache_generation = gen;
    return true;
}

// One linuxcnc.tool row.
PyObject *tool_row(const tooldata_entry_t &e)
{
    PyObject *row = PyStructSequence_New(lcnc_tool_type);
    if (!row) return nullptr;
    const EmcPose &o = e.offset;
    const double values[] = {o.tran.x, o.tran.y, o.tran.z, o.a, o.b, o.c, o.u, o.v, o.w,
                             e.diameter, e.frontangle, e.backangle};
    PyStructSequence_SET_ITEM(row, 0, PyLong_FromLong(e.toolno));
    for (int i = 0; i < 12; i++) PyStructSequence_SET_ITEM(row, i + 1, PyFloat_FromDouble(values[i]));
    PyStructSequence_SET_ITEM(row, 13, PyLong_FromLong(e.orientation));
    return row;
}

// d[key] = value (stealing); false on failure.
bool put(PyObject *d, const char *key, PyObject *value)
{
    if (!value) return false;
    int rc = PyDict_SetItemString(d, key, value);
    Py_DECREF(value);
    return rc == 0;
}

// The toolinfo dictionary of an entry.
PyObject *tool_dict(const tooldata_entry_t &e)
{
    static const char *const offset_keys[] = {"xoffset", "yoffset", "zoffset", "aoffset", "boffset",
                                             "coffset", "uoffset", "voffset", "woffset"};
    const EmcPose &o = e.offset;
    const double offsets[] = {o.tran.x, o.tran.y, o.tran.z, o.a, o.b, o.c, o.u, o.v, o.w};
    PyObject *d = PyDict_New();
    bool ok = d && put(d, "toolno", PyLong_FromLong(e.toolno)) &&
              put(d, "pocketno", PyLong_FromLong(e.pocketno)) &&
              put(d, "diameter", PyFloat_FromDouble(e.diameter)) &&
              put(d, "frontangle", PyFloat_FromDouble(e.frontangle)) &&
              put(d, "backangle", PyFloat_FromDouble(e.backangle)) &&
              put(d, "orientation", PyLong_FromLong(e.orientation));
    for (int i = 0; ok && i < 9; i++) ok = put(d, offset_keys[i], PyFloat_FromDouble(offsets[i]));
    ok = ok && put(d, "comment", lcnc_text(e.comment, sizeof e.comment));
    if (!ok) Py_XDECREF(d);
    return ok ? d : nullptr;
}

} // namespace

// Attach once per process; a missing segment is retried on later calls.
void lcnc_tool_attach()
{
    char err[256];
    tool_attach_tried = true;
    if (!tool_data) tool_data = tooldata_open(0, err, sizeof err);
}

// stat.tool_table
PyObject *lcnc_stat_tool_table(PyObject *, void *)
{
    if (!tool_attach_tried || !refresh_cache()) return PyTuple_New(0);
    PyObject *t = PyTuple_New(static_cast<Py_ssize_t>(tool_cache.size()));
    for (size_t i = 0; t && i < tool_cache.size(); i++) {
        PyObject *row = tool_row(tool_cache[i]);
        if (!row) {
            Py_DECREF(t);
            return nullptr;
        }
        PyTuple_SET_ITEM(t, static_cast<Py_ssize_t>(i), row);
    }
    return t;
}

// stat.toolinfo(toolno)
PyObject *lcnc_stat_toolinfo(PyObject *self, PyObject *args)
{
    int toolno = 0;
    if (!PyArg_ParseTuple(args, "i:toolinfo", &toolno)) return nullptr;
    if (!reinterpret_cast<PyStat *>(self)->polled || !tool_attach_tried) {
        PyErr_SetString(PyExc_ValueError, "toolinfo: NOT READY (initial poll reqd)");
        return nullptr;
    }
    if (toolno == 0) {
        PyErr_SetString(PyExc_ValueError,
                        "toolinfo: for tool in spindle: use linuxnc.stat.tool_table[0]");
        return nullptr;
    }
    if (refresh_cache()) {
        for (size_t i = 1; i < tool_cache.size(); i++)
            if (tool_cache[i].toolno == toolno) return tool_dict(tool_cache[i]);
    }
    PyErr_Format(PyExc_ValueError, "toolinfo: NO tooldata for toolno=%d", toolno);
    return nullptr;
}

// Create the linuxcnc.tool struct-sequence type.
int lcnc_add_tool(PyObject *module)
{
    lcnc_tool_type = PyStructSequence_NewType(&tool_desc);
    if (!lcnc_tool_type) return -1;
    Py_INCREF(lcnc_tool_type);
    return PyModule_AddObject(module, "tool", reinterpret_cast<PyObject *>(lcnc_tool_type)) < 0 ? -1 : 0;
}
