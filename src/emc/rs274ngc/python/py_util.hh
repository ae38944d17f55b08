// py_util.hh: small helpers of the embedded-Python plugin: owned references, the GIL, errors, output order.
#ifndef OPENEMC_RS274NGC_PY_UTIL_HH
#define OPENEMC_RS274NGC_PY_UTIL_HH

#include <Python.h>
#include <string>

// An owned reference, released when it goes out of scope.
class PyRef {
public:
    PyRef() = default;
    explicit PyRef(PyObject *o) : o_(o) {}
    PyRef(const PyRef &r) : o_(r.o_) { Py_XINCREF(o_); }
    PyRef &operator=(const PyRef &r)
    {
        Py_XINCREF(r.o_);
        Py_XDECREF(o_);
        o_ = r.o_;
        return *this;
    }
    ~PyRef() { Py_XDECREF(o_); }
    PyObject *get() const { return o_; }
    explicit operator bool() const { return o_ != nullptr; }
    // give the reference away
    PyObject *release()
    {
        PyObject *o = o_;
        o_ = nullptr;
        return o;
    }

private:
    PyObject *o_ = nullptr;
};

// Holds the GIL for as long as it lives (works whether or not this thread holds it already).
class GilLock {
public:
    GilLock() : state_(PyGILState_Ensure()) {}
    ~GilLock() { PyGILState_Release(state_); }
    GilLock(const GilLock &) = delete;
    GilLock &operator=(const GilLock &) = delete;

private:
    PyGILState_STATE state_;
};

// The pending Python exception as text: traceback lines then "Type: message"; clears it.
std::string py_error_text();
// Flush C stdio before Python prints, so output keeps its order.
void flush_c_output();
// Flush Python's sys.stdout and sys.stderr after it ran.
void flush_py_output();
// A Python str as UTF-8 std::string ("" when not a str).
std::string py_str(PyObject *o);

#endif
