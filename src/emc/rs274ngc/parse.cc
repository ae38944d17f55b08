// parse.cc: turns one source line into an evaluated Block (LinuxCNC's line syntax and modal groups).
#include <algorithm>
#include <cctype>
#include <iterator>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "interp.hh"

namespace {

constexpr size_t MAX_LINE = 253;

// Lower-case the line and drop blanks outside comments; ';' ends it. Comments keep their case.
std::string normalize(const std::string &raw)
{
    if (raw.size() >= MAX_LINE) throw InterpError("Command too long");
    std::string t;
    t.reserve(raw.size());
    for (size_t i = 0; i < raw.size(); i++) {
        char c = raw[i];
        if (c == ';') break;
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') continue;
        if (c != '(') {
            t += (c >= 'A' && c <= 'Z') ? (char)(c + 32) : c;
            continue;
        }
        size_t j = i + 1;
        for (; j < raw.size() && raw[j] != ')'; j++)
            if (raw[j] == '(') throw InterpError("Nested comment found");
        if (j >= raw.size()) throw InterpError("Unclosed comment found");
        t.append(raw, i, j - i + 1);
        i = j;
    }
    return t;
}

// modal group of a G code ×10, -1 if unknown
int g_group(int g)
{
    static const struct { int group; int codes[32]; } table[] = {
        {GG_NONMODAL, {40, 53, 100, 280, 281, 300, 301, 520, 530, 920, -1}},
        {GG_MOTION, {0, 10, 20, 30, 50, 51, 52, 330, 331, 382, 383, 384, 385, 700, 710, 711, 712,
                     720, 721, 722, 730, 740, 760, 800, -1}},
        {GG_PLANE, {170, 180, 190, 171, 181, 191, -1}},
        {GG_DISTANCE, {900, 910, -1}},
        {GG_IJK, {901, 911, -1}},
        {GG_FEED, {930, 940, 950, -1}},
        {GG_UNITS, {200, 210, -1}},
        {GG_COMP, {400, 410, 411, 420, 421, -1}},
        {GG_TOOL_LENGTH, {430, 431, 432, 490, -1}},
        {GG_RETRACT, {980, 990, -1}},
        {GG_COORD, {540, 550, 560, 570, 580, 590, 591, 592, 593, -1}},
        {GG_PATH, {610, 611, 640, -1}},
        {GG_SPINDLE, {960, 970, -1}},
        {GG_LATHE, {70, 80, -1}},
        {GG_G92, {921, 922, 923, -1}},
    };
    if (g >= 810 && g <= 890 && g % 10 == 0) return GG_MOTION;
    for (const auto &row : table)
        for (int i = 0; row.codes[i] != -1; i++)
            if (row.codes[i] == g) return row.group;
    return -1;
}

// modal group of an M code, -1 if unknown
int m_group(int m)
{
    static const struct { int group; int codes[9]; } table[] = {
        {MG_STOP, {0, 1, 2, 30, 60, 99, -1}},
        {MG_IO, {62, 63, 64, 65, 66, 67, 68, -1}},
        {MG_TOOL, {6, 61, -1}},
        {MG_SPINDLE, {3, 4, 5, 19, 70, 71, 72, 73, -1}},
        {MG_COOLANT, {7, 8, 9, -1}},
        {MG_OVERRIDE, {48, 49, 50, 51, 52, 53, -1}},
    };
    if (m >= 100 && m <= 199) return MG_USER;
    for (const auto &row : table)
        for (int i = 0; row.codes[i] != -1; i++)
            if (row.codes[i] == m) return row.group;
    return -1;
}

// integer within 0.0001 of v, else error
int to_int(double v)
{
    double r = std::nearbyint(v);
    if (std::fabs(v - r) > 0.0001 || std::fabs(r) > 2e9)
        throw InterpError("Non integer value for integer");
    return (int)r;
}

// map an O-word keyword to its kind
OKind okind(const std::string &k)
{
    static const struct { const char *name; OKind kind; } table[] = {
        {"sub", O_SUB}, {"endsub", O_ENDSUB}, {"call", O_CALL}, {"return", O_RETURN},
        {"if", O_IF}, {"elseif", O_ELSEIF}, {"else", O_ELSE}, {"endif", O_ENDIF},
        {"while", O_WHILE}, {"endwhile", O_ENDWHILE}, {"do", O_DO}, {"break", O_BREAK},
        {"continue", O_CONTINUE}, {"repeat", O_REPEAT}, {"endrepeat", O_ENDREPEAT},
    };
    for (const auto &e : table)
        if (k == e.name) return e.kind;
    return O_NONE;
}

} // namespace

// Parse a raw line into b (expressions evaluated with the current parameter values).
void Interp::parse_line(const std::string &raw, Block &b)
{
    INTERP_FRAME();
    std::string t = normalize(raw);
    b.py_code = semicolon_python(raw);
    size_t pos = 0;
    if (pos < t.size() && t[pos] == '/') {
        b.block_delete = true;
        pos++;
    }
    if (pos < t.size() && t[pos] == 'n') {
        pos++;
        size_t start = pos;
        while (pos < t.size() && isdigit((unsigned char)t[pos])) pos++;
        if (pos == start) throw InterpError("Bad format unsigned integer");
        if (pos < t.size() && t[pos] == '.') {
            pos++;
            while (pos < t.size() && isdigit((unsigned char)t[pos])) pos++;
        }
        b.has_line_number = true;
        b.line_number = atof(t.c_str() + start);
    }
    parse_words(t, pos, b);
}

// Parse everything after the line number.
void Interp::parse_words(const std::string &t, size_t pos, Block &b)
{
    INTERP_FRAME();
    bool words = false;
    while (pos < t.size()) {
        char c = t[pos];
        if (c == '(') {
            size_t end = t.find(')', pos);
            b.comment = t.substr(pos + 1, end - pos - 1);
            b.has_comment = true;
            pos = end + 1;
        } else if (c == 'o') {
            if (words || b.o_kind != O_NONE || b.o_fanuc)
                throw InterpError("Unexpected character after O-word");
            parse_oword(t, pos, b);
        } else if (b.o_kind != O_NONE || b.o_fanuc) {
            throw InterpError("Unexpected character after O-word");
        } else if (c == '#') {
            parse_assignment(t, pos, b);
            words = true;
        } else {
            parse_word(c, t, pos, b);
            words = true;
        }
    }
}

// Parse "#n=value" or "#<name>=value".
void Interp::parse_assignment(const std::string &t, size_t &pos, Block &b)
{
    INTERP_FRAME();
    pos++;
    std::string name;
    int index = 0;
    if (pos < t.size() && t[pos] == '<') {
        name = read_name(t, pos);
    } else {
        index = to_int(read_real_value(t, pos));
        if (index < 1 || index >= PARAM_COUNT) throw InterpError("Parameter number out of range");
    }
    if (pos >= t.size() || t[pos] != '=')
        throw InterpError("Equal sign missing in parameter setting");
    pos++;
    double v = read_real_value(t, pos);
    if (name.empty()) {
        check_numbered_writable(index);
        b.num_assign.emplace_back(index, v);
    } else {
        check_named_writable(name);
        b.named_assign.emplace_back(name, v);
    }
}

// Where word c of a block is stored: its presence flag and value.
static void word_slot(Block &b, char c, bool *&have, double *&value)
{
    if (c == '@') { have = &b.has_polar_radius; value = &b.polar_radius; return; }
    if (c == '^') { have = &b.has_polar_angle; value = &b.polar_angle; return; }
    if (c == '$') { have = &b.has_dollar; value = &b.dollar; return; }
    have = &b.has[c - 'a'];
    value = &b.val[c - 'a'];
}

// true for the letters (and @ ^ $) that form words other than G, M, N and O
static bool word_letter(char c)
{
    if (c == '@' || c == '^' || c == '$') return true;
    return c >= 'a' && c <= 'z' && !strchr("nouvw", c);
}

// Range and integer checks of a word's value; returns the value to store.
static double checked_word(char c, double v)
{
    static const struct { char letter; bool integer; const char *negative; } rules[] = {
        {'$', true, nullptr},
        {'f', false, "Negative f word used"},
        {'s', false, "Negative spindle speed used"},
        {'t', true, "Negative tool id used"},
        {'l', true, "Negative l word used"},
        {'h', true, "Negative h word tool length offset used"},
    };
    for (const auto &r : rules) {
        if (r.letter != c) continue;
        if (r.integer) v = to_int(v);
        if (r.negative && v < 0) throw InterpError(r.negative);
    }
    return v;
}

// Parse one letter word (or @ ^ $) at pos.
void Interp::parse_word(char c, const std::string &t, size_t &pos, Block &b)
{
    INTERP_FRAME();
    if (c == 'g') { parse_g(t, pos, b); return; }
    if (c == 'm') { parse_m(t, pos, b); return; }
    bool profile_uw = reading_profile_ && (c == 'u' || c == 'w');
    if (!word_letter(c) && !profile_uw)
        throw InterpError(std::string("Bad character '") + c + "' used");
    pos++;
    bool *have;
    double *value;
    word_slot(b, c, have, value);
    if (*have) throw InterpError(std::string("Multiple ") + c + " words on one line");
    double v = read_real_value(t, pos);
    *have = true;
    *value = checked_word(c, v);
}

// Parse a G word and file it in its modal group.
void Interp::parse_g(const std::string &t, size_t &pos, Block &b)
{
    INTERP_FRAME();
    pos++;
    double v = read_real_value(t, pos);
    if (v < 0) throw InterpError("Negative g code used");
    double tenths = v * 10.0;
    double code = std::nearbyint(tenths);
    if (std::fabs(tenths - code) > 0.001 || code > 999) throw InterpError("G-code out of range");
    int g = (int)code;
    int group = g_group(g);
    auto remap = g_remaps_.find(g);
    if (remap != g_remaps_.end()) group = remap->second.group;
    if (group < 0 || group >= GG_COUNT) throw InterpError("Unknown g code used");
    int &slot = b.g_modes[group];
    if (slot != -1 && group == GG_MOTION && (slot == 800 || g == 800)) {
        b.g80_dropped = true;
        if (slot == 800) slot = g;
        return;
    }
    if (slot != -1) throw InterpError("Two g codes used from same modal group");
    slot = g;
}

// Parse an M word and file it in its modal group.
void Interp::parse_m(const std::string &t, size_t &pos, Block &b)
{
    INTERP_FRAME();
    pos++;
    int m = to_int(read_real_value(t, pos));
    if (m < 0) throw InterpError("Negative m code used");
    auto remap = m_remaps_.find(m);
    if (remap != m_remaps_.end() && remap->second.builtin && remap_active(&remap->second))
        remap = m_remaps_.end();   // inside its own procedure a remapped built-in is the built-in
    if (m > 199 && remap == m_remaps_.end())
        throw InterpError("M-code greater than 199: M" + std::to_string(m));
    if (b.m_count >= 4) throw InterpError("Too many m codes on line");
    if (m == 98) {
        if (b.m98) throw InterpError("Two m codes used from same modal group");
        b.m98 = true;
        b.m_count++;
        return;
    }
    int group = remap != m_remaps_.end() ? remap->second.group : m_group(m);
    if (group < 0) throw InterpError("Unknown m code used: M" + std::to_string(m));
    if (b.m_modes[group] != -1) throw InterpError("Two m codes used from same modal group");
    b.m_modes[group] = m;
    b.m_count++;
}

// Parse "o<name>|oN|o[expr] keyword [args]".
void Interp::parse_oword(const std::string &t, size_t &pos, Block &b)
{
    INTERP_FRAME();
    pos++;
    if (pos < t.size() && t[pos] == '<') {
        b.o_name = read_name(t, pos);
    } else {
        double v = read_real_value(t, pos);
        char buf[32];
        snprintf(buf, sizeof buf, "%d", to_int(v));
        b.o_name = buf;
    }
    size_t start = pos;
    while (pos < t.size() && t[pos] >= 'a' && t[pos] <= 'z') pos++;
    std::string key = t.substr(start, pos - start);
    if (key.empty()) {
        b.o_fanuc = true;
        return;
    }
    b.o_kind = okind(key);
    if (b.o_kind == O_NONE) throw InterpError("Unknown word where unary operation could be");
    parse_o_args(t, pos, b);
}

// The bracketed arguments (call) or condition/value (if, while, return, ...) of an O-word,
// and comments between them.
void Interp::parse_o_args(const std::string &t, size_t &pos, Block &b)
{
    INTERP_FRAME();
    static const OKind with_value[] = {O_IF, O_ELSEIF, O_WHILE, O_RETURN, O_ENDSUB, O_REPEAT};
    bool takes_value = std::find(std::begin(with_value), std::end(with_value), b.o_kind) !=
                       std::end(with_value);
    while (pos < t.size() && (t[pos] == '[' || t[pos] == '(')) {
        if (t[pos] == '(') {
            size_t end = t.find(')', pos);
            b.comment = t.substr(pos + 1, end - pos - 1);
            b.has_comment = true;
            pos = end + 1;
            continue;
        }
        double v = eval_expression(t, pos);
        if (b.o_kind == O_CALL) {
            if (b.o_args.size() >= 30) throw InterpError("Too many arguments to subroutine call");
            b.o_args.push_back(v);
        } else if (takes_value && !b.o_has_expr) {
            b.o_has_expr = true;
            b.o_value = v;
        } else {
            throw InterpError("Unexpected character after O-word");
        }
    }
}

// Modal group of a built-in G code x10, -1 when it is not one (REMAP= refuses built-in codes).
int Interp::builtin_g_group(int g)
{
    return g_group(g);
}

// Modal group of a built-in M code, -1 when it is not one.
int Interp::builtin_m_group(int m)
{
    return m == 98 ? MG_STOP : m_group(m);
}
