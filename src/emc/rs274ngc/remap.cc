// remap.cc: REMAP= of G and M codes to NGC procedures (gcode.md §17 optional extension).
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

// the block's value of word letter c ('a'..'z', '@' = none)
bool block_word(const Block &b, char c, double &v)
{
    if (c < 'a' || c > 'z' || !b.has[c - 'a']) return false;
    v = b.val[c - 'a'];
    return true;
}

} // namespace

// Read the REMAP= lines: "<code> modalgroup=<n> argspec=<spec> ngc=<name>".
void Interp::load_remaps(const std::vector<std::string> &lines)
{
    INTERP_FRAME();
    for (const std::string &line : lines) {
        std::istringstream in(line);
        std::string code;
        in >> code;
        RemapDef def;
        def.ngc = remap_field(line, "ngc");
        def.argspec = remap_field(line, "argspec");
        std::string group = remap_field(line, "modalgroup");
        if (code.size() < 2 || def.ngc.empty()) {
            fprintf(stderr, "%s: REMAP=%s: only ngc= procedures with a G or M code are supported\n",
                    ini_path_.c_str(), line.c_str());
            continue;
        }
        char kind = (char)toupper((unsigned char)code[0]);
        double number = atof(code.c_str() + 1);
        if (kind == 'G') {
            def.group = group.empty() ? GG_MOTION : atoi(group.c_str());
            g_remaps_[clamp_int(number * 10)] = def;
        } else if (kind == 'M') {
            def.group = group.empty() ? MG_USER : atoi(group.c_str());
            m_remaps_[clamp_int(number)] = def;
        } else {
            fprintf(stderr, "%s: REMAP=%s: unsupported code\n", ini_path_.c_str(), line.c_str());
        }
    }
}

// Call the procedure of a remapped code on this block (or the modal remapped motion); true if called.
bool Interp::run_remap(Block &b)
{
    INTERP_FRAME();
    const RemapDef *def = nullptr;
    std::string code;
    if (b.remap_m != -1) {
        def = &m_remaps_[b.remap_m];
        code = "M" + std::to_string(b.remap_m);
    } else if (g_remaps_.count(s_.motion_mode) &&
               (b.remap_g != -1 || b.word('x') || b.word('y') || b.word('z'))) {
        def = &g_remaps_[s_.motion_mode];
        char buf[16];
        snprintf(buf, sizeof buf, "G%g", s_.motion_mode / 10.0);
        code = buf;
    } else if (b.remap_g != -1) {
        def = &g_remaps_[b.remap_g];
        code = "G" + std::to_string(b.remap_g / 10);
    }
    if (!def) return false;
    SubDef sub;
    if (!lookup_sub(def->ngc, sub))
        throw InterpError("Remap procedure " + def->ngc + " for " + code + " not found");
    bool positional = def->argspec.find('@') != std::string::npos;
    std::vector<double> args;
    std::map<std::string, double> named;
    for (char c : def->argspec) {
        if (c == '@' || c == '>' || c == '^' || c == 'N' || c == 'n') continue;
        double v;
        if (block_word(b, (char)tolower((unsigned char)c), v)) {
            if (positional) args.push_back(v);
            else named[std::string(1, (char)tolower((unsigned char)c))] = v;
        } else if (isupper((unsigned char)c)) {
            throw InterpError("user-defined " + code + ": missing: " + std::string(1, c));
        }
    }
    push_call(sub, def->ngc, args, false);
    calls_.back().remap = true;
    if (b.remap_m == -1 && def->group == GG_MOTION) calls_.back().remap_motion = s_.motion_mode;
    for (auto &kv : named) calls_.back().locals[kv.first] = kv.second;
    remap_level_++;
    return true;
}
