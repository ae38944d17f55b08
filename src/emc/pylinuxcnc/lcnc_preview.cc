// lcnc_preview.cc: preview helpers of the linuxcnc module: vertex9 (GEOMETRY transform), rotation offsets, retired drawing calls.
#include "lcnc_preview.hh"

#include <cmath>
#include <cstring>

namespace {

// Rotation centre and which rotary letters honour it (gui_rot_offsets / gui_respect_offsets).
struct RotationOffsets {
    double center[3] = {0, 0, 0};
    bool respect = false;
    bool letter[3] = {false, false, false}; // A, B, C named in the coordinates
} rot_offsets;

// Rotate p about coordinate axis `axis` (0 X, 1 Y, 2 Z) by deg degrees around centre c.
void rotate(double p[3], int axis, double deg, const double c[3])
{
    double r = deg * M_PI / 180.0, cs = std::cos(r), sn = std::sin(r);
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    double a = p[i] - c[i], b = p[j] - c[j];
    p[i] = c[i] + a * cs - b * sn;
    p[j] = c[j] + a * sn + b * cs;
}

} // namespace

// Apply a GEOMETRY string to a 9-axis point: letters are applied from the first to the last;
// X Y Z and U V W translate along x y z, A B C rotate about x y z (degrees), '-' before a
// letter reverses it, '!' makes rotations use the gui_rot_offsets centre for the rotary
// letters given to gui_respect_offsets. An empty geometry means "XYZ".
void lcnc_vertex9(const double pt9[9], double out[3], const char *geometry)
{
    static const char letters[] = "XYZABCUVW";
    const double zero[3] = {0, 0, 0};
    const char *g = (geometry && *geometry) ? geometry : "XYZ";
    bool respect = rot_offsets.respect || strchr(g, '!') != nullptr;
    out[0] = out[1] = out[2] = 0;
    for (size_t k = 0; g[k]; k++) {
        const char *hit = strchr(letters, g[k] & ~0x20);
        if (!hit || !*hit) continue;
        int idx = static_cast<int>(hit - letters);
        double v = pt9[idx] * ((k > 0 && g[k - 1] == '-') ? -1.0 : 1.0);
        if (idx < 3 || idx >= 6) {
            out[idx % 3] += v;
        } else {
            bool centred = respect && rot_offsets.letter[idx - 3];
            rotate(out, idx - 3, v, centred ? rot_offsets.center : zero);
        }
    }
}

namespace {

// vertex9(geometry, (x, y, z, a, b, c, u, v, w)) -> (x, y, z)
PyObject *py_vertex9(PyObject *, PyObject *args)
{
    const char *geometry = nullptr;
    double p[9];
    if (!PyArg_ParseTuple(args, "s(ddddddddd):vertex9", &geometry, &p[0], &p[1], &p[2], &p[3],
                          &p[4], &p[5], &p[6], &p[7], &p[8]))
        return nullptr;
    double out[3];
    lcnc_vertex9(p, out, geometry);
    return Py_BuildValue("(ddd)", out[0], out[1], out[2]);
}

// gui_rot_offsets(x, y, z): the centre rotations use when offsets are respected.
PyObject *py_gui_rot_offsets(PyObject *, PyObject *args)
{
    if (!PyArg_ParseTuple(args, "ddd:gui_rot_offsets", &rot_offsets.center[0],
                          &rot_offsets.center[1], &rot_offsets.center[2]))
        return nullptr;
    Py_RETURN_NONE;
}

// gui_respect_offsets(coordinates, respect): rotary letters of coordinates use the centre.
PyObject *py_gui_respect_offsets(PyObject *, PyObject *args)
{
    const char *coords = nullptr;
    int respect = 0;
    if (!PyArg_ParseTuple(args, "si:gui_respect_offsets", &coords, &respect)) return nullptr;
    rot_offsets.respect = respect != 0;
    for (int i = 0; i < 3; i++)
        rot_offsets.letter[i] = respect && (strchr(coords, "ABC"[i]) || strchr(coords, "abc"[i]));
    Py_RETURN_NONE;
}

// draw_lines, draw_dwells, line9: retired in LinuxCNC 2.10 (the preview draws from Python);
// kept so old GUI code still imports and runs. They draw nothing.
PyObject *py_retired(PyObject *, PyObject *)
{
    Py_RETURN_NONE;
}

PyMethodDef preview_functions[] = {
    {"vertex9", py_vertex9, METH_VARARGS, "vertex9(geometry, pos9) -> (x, y, z)"},
    {"gui_rot_offsets", py_gui_rot_offsets, METH_VARARGS, "gui_rot_offsets(x, y, z)"},
    {"gui_respect_offsets", py_gui_respect_offsets, METH_VARARGS, "gui_respect_offsets(coords, respect)"},
    {"draw_lines", py_retired, METH_VARARGS, "retired: draws nothing"},
    {"draw_dwells", py_retired, METH_VARARGS, "retired: draws nothing"},
    {"line9", py_retired, METH_VARARGS, "retired: draws nothing"},
    {nullptr, nullptr, 0, nullptr},
};

} // namespace

// Add the functions to the module.
int lcnc_add_preview(PyObject *module)
{
    return PyModule_AddFunctions(module, preview_functions);
}
