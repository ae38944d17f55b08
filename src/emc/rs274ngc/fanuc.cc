// fanuc.cc: Fanuc-style numbered programs: "O100" ... "M99" called by "M98 P100 [L n]".
#include <cctype>
#include <cmath>

#include "interp.hh"

// Fanuc label "O<n>" of a bare program-number line ("" when the line is not one).
std::string fanuc_label_name(const std::string &line)
{
    size_t i = line.find_first_not_of(" \t");
    if (i != std::string::npos && line[i] == '/') i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || (line[i] != 'o' && line[i] != 'O')) return "";
    size_t k = line.find_first_not_of(" \t", i + 1);
    size_t start = k;
    while (k < line.size() && isdigit((unsigned char)line[k])) k++;
    if (k == start || start == std::string::npos) return "";
    std::string digits = line.substr(start, k - start);
    k = line.find_first_not_of(" \t", k);
    if (k != std::string::npos && line[k] != '(' && line[k] != ';') return "";
    return std::to_string(atol(digits.c_str()));
}

// A bare "O<n>" met in normal flow: a program title, or the start of a program execution
// simply runs into (numbered programs are not skipped).
InterpStatus Interp::fanuc_label(Block &)
{
    INTERP_FRAME();
    if (s_.settings.disable_fanuc_style_sub)
        throw InterpError("DISABLE_FANUC_STYLE_SUB set in .ini file, but found O-word without "
                          "keyword");
    return INTERP_OK;
}

// M98 P<n> [L<count>]: call Fanuc subprogram n, which must follow the call in the file.
void Interp::fanuc_call(Block &b)
{
    INTERP_FRAME();
    if (s_.settings.disable_fanuc_style_sub)
        throw InterpError("DISABLE_FANUC_STYLE_SUB set in .ini file, but found m98");
    if (!b.word('p')) throw InterpError("Found 'm98' code with no P-word");
    std::string name = std::to_string(clamp_int(b.value('p')));
    SubDef def;
    if (!find_sub(name, def, true)) sub_not_found(name, true);
    long count = b.word('l') ? clamp_int(b.value('l')) : 1;
    if (count < 1) return;
    push_call(def, name, {}, true);
    calls_.back().fanuc_count = count;
}

// M99: loop a Fanuc subprogram for L or return from it; false in the main program.
bool Interp::fanuc_return()
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (calls_.size() > 1 && !f.fanuc)
        throw InterpError("'O.... endsub' or 'O.... return' must follow 'O.... sub' subroutine "
                          "definition");
    if (!f.fanuc) return false;
    count_iteration(f.fanuc_iterations, f.sub_name);
    if (--f.fanuc_count > 0) {
        f.pos = f.sub_line + 1;
        return true;
    }
    pop_call();
    return true;
}
