// interp_base.hh: the abstract interpreter rs274 drives; the built-in Interp and plugins (-p x.so) implement it.
#ifndef OPENEMC_RS274NGC_INTERP_BASE_HH
#define OPENEMC_RS274NGC_INTERP_BASE_HH

#include <functional>
#include <string>
#include <vector>

#include "canon.hh"

// Result of executing one line.
enum InterpStatus { INTERP_OK = 0, INTERP_EXIT = 1, INTERP_EXECUTE_FINISH = 2,
                    INTERP_ENDFILE = 3, INTERP_ERROR = 4 };

// Reads a HAL pin, parameter or signal for #<_hal[name]>; false when there is no such item.
using HalReader = std::function<bool(const std::string &name, double &value)>;
// Runs user M-code M<m> (100..199) with its P and Q words; false when no program M<m> exists.
using UserMHandler = std::function<bool(int m, double p, double q)>;

// What a program driver (rs274, task) needs from an interpreter.
class InterpBase {
public:
    virtual ~InterpBase() = default;
    // read settings from an INI file; false if unloadable
    virtual bool load_ini(const std::string &path) = 0;
    // parameter (.var) file path
    virtual void set_var_file(const std::string &path) = 0;
    // tool table (index 0 = spindle)
    virtual void set_tools(const std::vector<CanonTool> &tools) = 0;
    // #<_task>
    virtual void set_task(bool task) = 0;
    // block delete switch
    virtual void set_block_delete(bool on) = 0;
    // M99 in the main program goes back to its first line (task) instead of ending it (rs274)
    virtual void set_loop_on_main_m99(bool) {}
    // source of #<_hal[...]> values (none in rs274: they are not defined)
    virtual void set_hal_reader(HalReader) {}
    // runner of M100-M199 (none in rs274: "Unknown m code used")
    virtual void set_user_m_handler(UserMHandler) {}
    // initialise (throws InterpError-like std::runtime_error on failure)
    virtual void init() = 0;
    // open a program file (throws on failure)
    virtual void open(const std::string &path) = 0;
    // execute the next line of the open program
    virtual InterpStatus execute_next() = 0;
    // execute one MDI line
    virtual InterpStatus execute_line(const std::string &text) = 0;
    // close the program
    virtual void close() = 0;
    // shut down
    virtual void exit() = 0;
    // last error text and its source line
    virtual const std::string &error_text() const = 0;
    virtual const std::string &error_line() const = 0;
    // functions the last error unwound through, innermost first (rs274 -s); may be empty
    virtual const std::vector<std::string> &error_stack() const
    {
        static const std::vector<std::string> none;
        return none;
    }
    // true when the last error was the end of the file
    virtual bool at_end_of_file() const = 0;
    // text of the line being executed (canon N markers)
    virtual const std::string &line_text() const = 0;
};

// Plugins export this factory as extern "C" symbol "make_interp".
typedef InterpBase *(*MakeInterpFn)(Canon &out);

#endif
