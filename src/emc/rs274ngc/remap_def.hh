// remap_def.hh: one REMAP= definition and one running remap (gcode.md §17, LinuxCNC's remap documentation).
#ifndef OPENEMC_RS274NGC_REMAP_DEF_HH
#define OPENEMC_RS274NGC_REMAP_DEF_HH

#include <map>
#include <memory>
#include <string>

#include "block.hh"

// What a REMAP= line says about one code.
struct RemapDef {
    std::string code;              // as the user wrote it, upper case: "M400", "G88.1", "T", "M6"
    char letter = 0;               // 'G', 'M', 'T', 'S' or 'F'
    int number = -1;               // G code x10 or M code number; -1 for T, S, F
    int group = -1;                // modal group the code executes with
    std::string argspec;           // upper = required, lower = optional, '@' positional, '^' '>' 'n'
    std::string ngc;               // O-word procedure (file basename); "" when python= is used
    std::string python;            // python= / py= body function in module remap
    std::string prolog, epilog;    // Python functions in module remap, "" when absent
    bool builtin = false;          // T, S, F or a built-in M code: inside its own procedure the code is built-in
    std::string ini_file;          // where the line is, for messages
    int ini_line = 0;

    // name of the procedure the generated call line names ("O <name> call ")
    const std::string &proc() const { return ngc.empty() ? python : ngc; }
    // true when any part needs the Python plugin
    bool needs_python() const { return !python.empty() || !prolog.empty() || !epilog.empty(); }
};

// A suspended Python generator (yield INTERP_EXECUTE_FINISH), owned by the Python plugin.
using PyGenerator = std::shared_ptr<void>;

// Phase of a running remap.
enum RemapPhase { REMAP_PROLOG, REMAP_BODY_NGC, REMAP_BODY_PY, REMAP_EPILOG };

// One remapped code being executed (remap level = index + 1).
struct RemapCall {
    const RemapDef *def = nullptr;
    Block block;                   // the block that holds the code; the code itself is consumed
    size_t resume_step = 0;        // block step to continue with when the remap completes
    size_t frame = 0;              // index in the call stack of the frame the remap pushed
    RemapPhase phase = REMAP_PROLOG;
    PyGenerator generator;         // set while a prolog, body or epilog is suspended
    std::string call_line;         // "O <name> call " (echoed with errors)
    std::map<std::string, double> words;  // the argspec words, passed to Python as keywords
};

#endif
