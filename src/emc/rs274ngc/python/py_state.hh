// py_state.hh: interpreter attributes by name, for the private `_rs274ngc` module.
#ifndef OPENEMC_RS274NGC_PY_STATE_HH
#define OPENEMC_RS274NGC_PY_STATE_HH

#include <string>

#include "py_util.hh"

// Value of interpreter attribute `name`; nullptr with AttributeError when there is none.
PyObject *state_get(const std::string &name);
// Set interpreter attribute `name`; false with a Python error set.
bool state_set(const std::string &name, PyObject *value);
// Names of all interpreter attributes (for dir()).
PyObject *state_names();
// A block as a dict (letters, modes, comment, O-call arguments, executing remap).
PyObject *block_dict(const struct Block &b, const struct RemapDef *executing);
// A REMAP definition as a dict.
PyObject *remap_dict(const struct RemapDef &d);

#endif
