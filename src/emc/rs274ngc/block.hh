// block.hh: one parsed RS274/NGC line (words already evaluated), shared by interpreter, cycles and cutter comp.
#ifndef OPENEMC_RS274NGC_BLOCK_HH
#define OPENEMC_RS274NGC_BLOCK_HH

#include <string>
#include <utility>
#include <vector>

// G modal groups (LinuxCNC's modal groups); index into Block::g_modes.
enum GGroup { GG_NONMODAL = 0, GG_MOTION = 1, GG_PLANE = 2, GG_DISTANCE = 3, GG_IJK = 4,
              GG_FEED = 5, GG_UNITS = 6, GG_COMP = 7, GG_TOOL_LENGTH = 8, GG_RETRACT = 10,
              GG_COORD = 12, GG_PATH = 13, GG_SPINDLE = 14, GG_LATHE = 15, GG_G92 = 16,
              GG_COUNT = 17 };

// M modal groups (LinuxCNC's modal groups); index into Block::m_modes.
enum MGroup { MG_STOP = 4, MG_IO = 5, MG_TOOL = 6, MG_SPINDLE = 7, MG_COOLANT = 8,
              MG_OVERRIDE = 9, MG_USER = 10, MG_COUNT = 11 };

// O-word keyword of a line.
enum OKind { O_NONE, O_SUB, O_ENDSUB, O_CALL, O_RETURN, O_IF, O_ELSEIF, O_ELSE, O_ENDIF,
             O_WHILE, O_ENDWHILE, O_DO, O_BREAK, O_CONTINUE, O_REPEAT, O_ENDREPEAT };

// A parsed, evaluated block.
struct Block {
    bool has[26] = {};          // letter words a..z present ('a' -> 0)
    double val[26] = {};        // their values
    int g_modes[GG_COUNT];      // G code ×10 per group, -1 if absent
    int m_modes[MG_COUNT];      // M code per group, -1 if absent
    int m_count = 0;
    bool has_polar_radius = false, has_polar_angle = false;  // '@' and '^'
    double polar_radius = 0, polar_angle = 0;
    bool has_dollar = false;    // '$' spindle selector
    double dollar = 0;
    bool has_line_number = false;
    double line_number = 0;
    bool g80_dropped = false;   // explicit G80 silently dropped next to another motion code
    std::string comment;        // last (...) comment text, case kept
    bool has_comment = false;
    std::string py_code;        // ";py,..." / ";pyrun,..." / ";pyreload" text after the ';' (embedded Python)
    std::vector<std::pair<int, double>> num_assign;          // #n=value
    std::vector<std::pair<std::string, double>> named_assign; // #<name>=value
    OKind o_kind = O_NONE;
    std::string o_name;         // "123" or "name" (lower case)
    bool o_has_expr = false;    // expression/argument after if/while/return/...
    double o_value = 0;
    std::vector<double> o_args; // call arguments
    bool o_fanuc = false;       // "O100" without keyword: Fanuc program/sub number
    bool m98 = false;           // M98 Fanuc-style call
    bool block_delete = false;  // line starts with '/'
    bool execute_finish = false; // a step asked for execute-finish (probe, tool change)
    int status = 0;             // InterpStatus a step ended the block with (0 = OK)

    Block() { for (int &g : g_modes) g = -1; for (int &m : m_modes) m = -1; }
    // true when letter word c ('a'..'z') is present
    bool word(char c) const { return has[c - 'a']; }
    // value of letter word c
    double value(char c) const { return val[c - 'a']; }
    // motion code of this block (group 1), -1 if none
    int motion() const { return g_modes[GG_MOTION]; }
};

#endif
