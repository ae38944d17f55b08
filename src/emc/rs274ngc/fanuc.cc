// fanuc.cc: Fanuc-style numbered subprograms: "O100" ... "M99" called by "M98 P100 [L n]".
#include <cctype>
#include <cmath>

#include "interp.hh"

namespace {

// true when a line holds an M99 word (comments ignored)
bool has_m99(const std::string &line)
{
    std::string t;
    for (char c : line) {
        if (c == '(' || c == ';') break;
        if (c != ' ' && c != '\t') t += (char)tolower((unsigned char)c);
    }
    for (size_t i = t.find("m99"); i != std::string::npos; i = t.find("m99", i + 1))
        if (i + 3 >= t.size() || !isdigit((unsigned char)t[i + 3])) return true;
    return false;
}

// Fanuc label "O<n>" of a line, or "" when the line is not one
std::string fanuc_name(const std::string &line)
{
    size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || (line[i] != 'o' && line[i] != 'O')) return "";
    size_t k = i + 1;
    while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) k++;
    size_t start = k;
    while (k < line.size() && isdigit((unsigned char)line[k])) k++;
    if (k == start) return "";
    while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) k++;
    if (k < line.size() && line[k] != '(' && line[k] != ';') return "";
    return std::to_string(atol(line.c_str() + start));
}

} // namespace

// An "O<n>" line met in normal flow: a program number at the top, else a subprogram to skip.
InterpStatus Interp::fanuc_label(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (f.fanuc) return INTERP_OK;
    for (size_t i = 0; i + 1 < f.pos; i++) {
        const std::string &l = f.file->lines[i];
        size_t nb = l.find_first_not_of(" \t");
        if (nb == std::string::npos || l[nb] == '%' || l[nb] == '(' || l[nb] == ';') continue;
        skip_fanuc_ = true;
        skipping_ = true;
        skip_name_ = b.o_name;
        return INTERP_OK;
    }
    return INTERP_OK;
}

// While skipping a Fanuc subprogram body: true at its M99 line.
bool Interp::fanuc_skip_done(const std::string &line)
{
    INTERP_FRAME();
    if (!has_m99(line)) return false;
    skipping_ = false;
    skip_fanuc_ = false;
    return true;
}

// M98 P<n> [L<count>]: call a Fanuc subprogram of the main file.
void Interp::fanuc_call(Block &b)
{
    INTERP_FRAME();
    if (s_.settings.disable_fanuc_style_sub) throw InterpError("Unknown m code used: M98");
    if (!b.word('p')) throw InterpError("Found 'm98' code with no P-word");
    std::string name = std::to_string(clamp_int(b.value('p')));
    std::shared_ptr<SourceFile> file = calls_.back().file;
    size_t line = 0;
    bool found = false;
    for (size_t i = 0; i < file->lines.size() && !found; i++) {
        if (fanuc_name(file->lines[i]) == name) {
            line = i;
            found = true;
        }
    }
    if (!found)
        throw InterpError("Unable to find O-word " + name + " for M98 call");
    long count = b.word('l') ? clamp_int(b.value('l')) : 1;
    if (count < 1) return;
    push_call(SubDef{file, line}, name, {}, true);
    calls_.back().fanuc_count = count;
}

// M99 inside a Fanuc subprogram: loop for L or return; false in the main program.
bool Interp::fanuc_return()
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (!f.fanuc) return false;
    count_iteration(f.fanuc_iterations, f.sub_name);
    if (--f.fanuc_count > 0) {
        f.pos = f.sub_line + 1;
        return true;
    }
    pop_call();
    return true;
}
