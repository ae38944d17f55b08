// remap_config.cc: reads and checks the [RS274NGC]REMAP= lines (LinuxCNC remap documentation, "The REMAP statement").
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "inifile.hh"
#include "../interp.hh"

namespace {

// Characters an argspec may hold: [@A-NP-Za-np-z^>] (L too: M66 remaps take its wait mode).
bool argspec_char_ok(char c)
{
    if (c == '@' || c == '^' || c == '>') return true;
    char u = (char)toupper((unsigned char)c);
    return u >= 'A' && u <= 'Z' && u != 'O';
}

// Built-in M codes that may be remapped (the "existing codes" list) with their own modal group.
int remappable_builtin_m_group(int m)
{
    switch (m) {
    case 0: case 1: case 60: return MG_STOP;
    case 6: case 61: return MG_TOOL;
    case 7: case 8: case 9: return MG_COOLANT;
    case 62: case 63: case 64: case 65: case 66: case 67: case 68: return MG_IO;
    default: return -1;
    }
}

// Split "key=value"; false when there is no '='.
bool split_option(const std::string &word, std::string &key, std::string &value)
{
    size_t eq = word.find('=');
    if (eq == std::string::npos || eq == 0) return false;
    key = word.substr(0, eq);
    for (char &c : key) c = (char)tolower((unsigned char)c);
    value = word.substr(eq + 1);
    return true;
}

} // namespace

// Parse the code word of a REMAP line into def; "" on success, else the problem.
std::string Interp::remap_parse_code(const std::string &word, RemapDef &def) const
{
    std::string code;
    for (char c : word) code += (char)toupper((unsigned char)c);
    def.code = code;
    def.letter = code[0];
    def.builtin = code == "T" || code == "S" || code == "F";
    if (def.builtin) return "";
    if (def.letter != 'G' && def.letter != 'M')
        return "code must be T, S, F or a G or M code";
    char *end = nullptr;
    double v = strtod(code.c_str() + 1, &end);
    if (end == code.c_str() + 1 || *end || v < 0) return "bad code number";
    if (def.letter == 'M') {
        if (v != std::floor(v) || v > 999) return "M code must be an integer from 0 to 999";
        def.number = (int)v;
        def.builtin = builtin_m_group(def.number) >= 0;
        bool user_m = def.number >= 100 && def.number <= 199;
        if (def.builtin && !user_m && remappable_builtin_m_group(def.number) < 0)
            return "this built-in M code cannot be remapped";
        return "";
    }
    double tenths = std::nearbyint(v * 10);
    if (std::fabs(v * 10 - tenths) > 1e-6 || tenths > 999) return "G code must have at most one decimal";
    def.number = (int)tenths;
    if (builtin_g_group(def.number) >= 0) return "this built-in G code cannot be remapped";
    return "";
}

// Apply one key=value option of a REMAP line; "" on success, else the problem.
std::string Interp::remap_parse_option(const std::string &key, const std::string &value,
                                       RemapDef &def) const
{
    if (key == "modalgroup") {
        char *end = nullptr;
        long g = strtol(value.c_str(), &end, 10);
        if (value.empty() || *end) return "modalgroup must be a number";
        def.group = (int)g;
        return "";
    }
    if (key == "argspec") {
        for (char c : value)
            if (!argspec_char_ok(c)) return std::string("argspec: invalid character '") + c + "'";
        def.argspec = value;
        return "";
    }
    std::string *slot = key == "ngc" ? &def.ngc : key == "python" || key == "py" ? &def.python
                        : key == "prolog" ? &def.prolog : key == "epilog" ? &def.epilog : nullptr;
    if (!slot) return "unknown option '" + key + "'";
    if (value.empty()) return key + "= needs a name";
    *slot = value;
    return "";
}

// Default and check the modal group of def; "" when fine.
std::string Interp::remap_check_group(RemapDef &def) const
{
    if (def.letter == 'T' || def.letter == 'S' || def.letter == 'F') {
        def.group = -1;
        return "";
    }
    if (def.letter == 'G') {
        if (def.group == -1) def.group = GG_MOTION;
        if (def.group != GG_MOTION) return "G codes can only be remapped in modalgroup 1";
        return "";
    }
    if (def.group == -1) def.group = MG_USER;
    bool stop_code = remappable_builtin_m_group(def.number) == MG_STOP;
    if (def.group < MG_IO || def.group > MG_USER) {
        if (!(stop_code && def.group == MG_STOP)) return "M codes can only be remapped in modalgroup 5 to 10";
    }
    return "";
}

// Parse one REMAP line; "" on success, else the problem.
std::string Interp::remap_parse_line(const std::string &line, RemapDef &def) const
{
    std::istringstream in(line);
    std::string word;
    if (!(in >> word)) return "no code given";
    std::string err = remap_parse_code(word, def);
    if (!err.empty()) return err;
    while (in >> word) {
        std::string key, value;
        if (!split_option(word, key, value)) return "expected key=value, got '" + word + "'";
        err = remap_parse_option(key, value, def);
        if (!err.empty()) return err;
    }
    if (!def.ngc.empty() && !def.python.empty()) return "ngc= and python= are mutually exclusive";
    if (def.ngc.empty() && def.python.empty()) return "needs ngc= or python=";
    return remap_check_group(def);
}

// Read every [RS274NGC]REMAP= line; a bad line is reported with file:line and ignored.
void Interp::load_remaps(const IniFile &ini)
{
    INTERP_FRAME();
    g_remaps_.clear();
    m_remaps_.clear();
    letter_remaps_.clear();
    for (int n = 1;; n++) {
        const IniEntry *e = ini.FindEntry("REMAP", "RS274NGC", n);
        if (!e) break;
        RemapDef def;
        def.ini_file = e->file;
        def.ini_line = e->line;
        std::string err = remap_parse_line(e->value, def);
        std::map<int, RemapDef> *table = def.letter == 'G' ? &g_remaps_ : &m_remaps_;
        bool dup = def.number >= 0 ? table->count(def.number) != 0 : letter_remaps_.count(def.letter) != 0;
        if (err.empty() && dup) err = def.code + " is already remapped";
        if (!err.empty()) {
            fprintf(stderr, "%s:%d: REMAP=%s: %s\n", e->file.c_str(), e->line, e->value.c_str(), err.c_str());
            continue;
        }
        if (def.number >= 0)
            (*table)[def.number] = def;
        else
            letter_remaps_[def.letter] = def;
    }
    have_remaps_ = !g_remaps_.empty() || !m_remaps_.empty() || !letter_remaps_.empty();
}

// The remap of letter word c ('t', 's' or 'f'), nullptr when not remapped.
const RemapDef *Interp::letter_remap(char c) const
{
    auto it = letter_remaps_.find((char)toupper((unsigned char)c));
    return it == letter_remaps_.end() ? nullptr : &it->second;
}
