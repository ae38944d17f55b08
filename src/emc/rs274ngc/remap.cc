// remap.cc: REMAP= of G and M codes to NGC procedures, run at their modal group's step.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "interp.hh"

namespace {

// value of "key=value" in a REMAP line, "" when absent
std::string remap_field(const std::string &line, const std::string &key)
{
    std::istringstream in(line);
    std::string word;
    while (in >> word) {
        if (word.size() > key.size() && word.compare(0, key.size() + 1, key + "=") == 0)
            return word.substr(key.size() + 1);
    }
    return "";
}

// the block's value of word letter c ('a'..'z'); false when absent
bool block_word(const Block &b, char c, double &v)
{
    if (c < 'a' || c > 'z' || !b.has[c - 'a']) return false;
    v = b.val[c - 'a'];
    return true;
}

// true for the argspec characters that name a word
bool argspec_word(char c)
{
    return isalpha((unsigned char)c) && c != 'n' && c != 'N';
}

} // namespace

// "G88.1" for code 881.
std::string g_code_text(int g)
{
    char buf[16];
    snprintf(buf, sizeof buf, "G%g", g / 10.0);
    return buf;
}

// Read one REMAP= line into def; false (with a message on stderr) when it cannot be used.
bool Interp::parse_remap(const std::string &line, RemapDef &def, char &kind, double &number) const
{
    INTERP_FRAME();
    std::istringstream in(line);
    std::string code;
    in >> code;
    def.ngc = remap_field(line, "ngc");
    def.argspec = remap_field(line, "argspec");
    std::string group = remap_field(line, "modalgroup");
    kind = code.empty() ? 0 : (char)toupper((unsigned char)code[0]);
    number = code.size() > 1 ? atof(code.c_str() + 1) : -1;
    if (def.ngc.empty() || (kind != 'G' && kind != 'M') || number < 0) {
        fprintf(stderr, "%s: REMAP=%s: only ngc= procedures of G or M codes are supported\n",
                ini_path_.c_str(), line.c_str());
        return false;
    }
    def.group = kind == 'G' ? (int)GG_MOTION : (int)MG_USER;
    if (group.empty()) return true;
    int g = atoi(group.c_str());
    bool ok = kind == 'G' ? g == GG_MOTION : (g >= MG_IO && g <= MG_USER);
    if (!ok) {
        fprintf(stderr, "%s: REMAP=%s: modalgroup=%d not supported for %c codes\n",
                ini_path_.c_str(), line.c_str(), g, kind);
        return false;
    }
    def.group = g;
    return true;
}

// Read the REMAP= lines: "<code> modalgroup=<n> argspec=<spec> ngc=<name>".
void Interp::load_remaps(const std::vector<std::string> &lines)
{
    INTERP_FRAME();
    for (const std::string &line : lines) {
        RemapDef def;
        char kind;
        double number;
        if (!parse_remap(line, def, kind, number)) continue;
        if (kind == 'G')
            g_remaps_[clamp_int(number * 10)] = def;
        else
            m_remaps_[clamp_int(number)] = def;
    }
}

// True when the motion step of this block runs the remapped G code of the motion mode.
bool Interp::remapped_motion(const Block &b) const
{
    int explicit_motion = b.motion();
    int m = explicit_motion != -1 ? explicit_motion : s_.motion_mode;
    if (!g_remaps_.count(m)) return false;
    if (explicit_motion != -1) return true;
    return b.word('x') || b.word('y') || b.word('z') || b.word('a') || b.word('b') ||
           b.word('c');
}

// The remapped codes of a block, with their definitions and code texts.
std::vector<std::pair<const RemapDef *, std::string>> Interp::block_remaps(const Block &b) const
{
    std::vector<std::pair<const RemapDef *, std::string>> out;
    for (int g = MG_IO; g <= MG_USER; g++)
        if (b.m_modes[g] != -1 && m_remaps_.count(b.m_modes[g]))
            out.emplace_back(&m_remaps_.at(b.m_modes[g]), "M" + std::to_string(b.m_modes[g]));
    if (remapped_motion(b)) {
        int m = b.motion() != -1 ? b.motion() : s_.motion_mode;
        out.emplace_back(&g_remaps_.at(m), g_code_text(m));
    }
    return out;
}

// The error line LinuxCNC reports for a remap's own errors: the call it generates.
static std::string remap_call_line(const RemapDef &def)
{
    return "O <" + def.ngc + "> call ";
}

// Before any other check: every remapped code's required words are on the line.
void Interp::check_remap_args(const Block &b)
{
    INTERP_FRAME();
    for (auto &r : block_remaps(b)) {
        std::string missing;
        for (char c : r.first->argspec)
            if (argspec_word(c) && isupper((unsigned char)c) && !b.word((char)tolower(c)))
                missing += c;
        if (!missing.empty())
            throw InterpErrorAt("user-defined " + r.second + ": missing: " + missing,
                                remap_call_line(*r.first));
    }
}

// When the remapped code runs: its spindle (^) and feed (>) preconditions hold.
void Interp::check_remap_state(const RemapDef &def, const std::string &code) const
{
    if (def.argspec.find('^') != std::string::npos && s_.speed[0] <= 0)
        throw InterpErrorAt(code + ": spindle speed must be greater than 0", remap_call_line(def));
    if (def.argspec.find('>') != std::string::npos && s_.feed_rate <= 0)
        throw InterpErrorAt(code + ": feed rate must be greater than 0", remap_call_line(def));
}

// True when word letter c ('a'..'z') is an argument of a remapped code of the block.
bool Interp::remap_uses_word(const Block &b, char c) const
{
    for (auto &r : block_remaps(b))
        for (char a : r.first->argspec)
            if (argspec_word(a) && tolower((unsigned char)a) == c) return true;
    return false;
}

// Call the procedure of a remapped code: arguments from the block as named locals (or
// positional with '@'); the rest of the block runs from step `resume` when it returns.
void Interp::start_remap(const Block &b, const RemapDef &def, const std::string &code, size_t resume)
{
    INTERP_FRAME();
    check_remap_state(def, code);
    SubDef sub;
    if (!lookup_sub(def.ngc, sub))
        throw InterpErrorAt("Remap procedure " + def.ngc + " for " + code + " not found",
                            remap_call_line(def));
    bool positional = def.argspec.find('@') != std::string::npos;
    std::vector<double> args;
    std::map<std::string, double> named;
    for (char c : def.argspec) {
        double v;
        if (c == 'n' || c == 'N') named["n"] = s_.sequence_number;
        if (!argspec_word(c) || !block_word(b, (char)tolower((unsigned char)c), v)) continue;
        if (positional) args.push_back(v);
        else named[std::string(1, (char)tolower((unsigned char)c))] = v;
    }
    int motion = s_.motion_mode;
    push_call(sub, def.ngc, args, false);
    CallFrame &f = calls_.back();
    f.remap = true;
    if (def.group == GG_MOTION && code[0] == 'G') f.remap_motion = b.motion() != -1 ? b.motion() : motion;
    for (auto &kv : named) f.locals[kv.first] = kv.second;
    f.resume_block = std::make_shared<Block>(b);
    f.resume_step = resume;
    remap_level_++;
}
