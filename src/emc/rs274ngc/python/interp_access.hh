// interp_access.hh: the interpreter internals the embedded Python's `interpreter` and `emccanon` modules reach.
#ifndef OPENEMC_RS274NGC_INTERP_ACCESS_HH
#define OPENEMC_RS274NGC_INTERP_ACCESS_HH

#include <string>
#include <vector>

#include "../interp.hh"

// Attribute bits of a named parameter as Python sees them (LinuxCNC's PA_* values).
enum ParamAttr { PA_READONLY = 1, PA_GLOBAL = 2, PA_UNSET = 4, PA_USE_LOOKUP = 8, PA_FROM_INI = 16,
                 PA_PYTHON = 32 };

// Friend of Interp: one accessor per piece of state the Python modules read or change.
struct InterpAccess {
    static InterpState &state(Interp &i) { return i.s_; }
    static Canon &canon(Interp &i) { return i.out(); }
    // the canon behind cutter compensation (for calls that are not queued behind held moves)
    static Canon &real_canon(Interp &i) { return i.real_out_; }
    static std::vector<CallFrame> &frames(Interp &i) { return i.calls_; }
    static const std::vector<RemapCall> &remaps(Interp &i) { return i.remap_stack_; }
    static const Block *current_block(Interp &i) { return i.current_block_; }
    static std::map<std::string, double> &globals(Interp &i) { return i.globals_; }
    static std::map<std::string, double> &ini_cache(Interp &i) { return i.ini_cache_; }
    static const std::set<std::string> &python_params(Interp &i) { return i.py_named_; }
    static double &return_value(Interp &i) { return i.value_; }
    static double &value_returned(Interp &i) { return i.value_returned_; }
    static bool task(Interp &i) { return i.task_; }
    static std::string &errormsg(Interp &i) { return i.py_errormsg_; }
    static bool &finish_request(Interp &i) { return i.py_finish_request_; }
    static const std::map<int, RemapDef> &g_remaps(Interp &i) { return i.g_remaps_; }
    static const std::map<int, RemapDef> &m_remaps(Interp &i) { return i.m_remaps_; }
    static const std::map<char, RemapDef> &letter_remaps(Interp &i) { return i.letter_remaps_; }
    static const std::string &ini_file(Interp &i) { return i.ini_path_; }
    static const std::string &error_text(Interp &i) { return i.error_; }
    // names of the built-in predefined parameters (#<_x>, #<_metric>, ...)
    static std::vector<std::string> predefined_names() { return Interp::predefined_names(); }
    static bool predefined(Interp &i, const std::string &name, double &v) { return i.predefined(name, v); }
    // self.execute(): one line now, with any procedure it calls
    static InterpStatus execute(Interp &i, const std::string &text) { return i.execute_nested(text); }
    // tool-data index of tool number n, -1 when absent
    static int find_tool(Interp &i, int toolno) { return i.find_tool_index(toolno); }
    // machine coordinates of a program-coordinate pose
    static Pose to_machine(Interp &i, const Pose &p) { return i.program_to_machine_pose(p); }
    // write a numbered parameter (range and read-only checks as for #n=)
    static void set_numbered(Interp &i, int n, double v)
    {
        i.check_numbered_writable(n);
        i.s_.params[n] = v;
    }
    // write a named parameter (read-only check as for #<name>=)
    static void set_named(Interp &i, const std::string &name, double v)
    {
        i.check_named_writable(name);
        i.set_named(name, v);
    }
};

#endif
