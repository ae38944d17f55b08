// rsh_format.cc: word splitting, argument parsing and the unit/program-code texts of linuxcncrsh replies.
#include "rsh_format.hh"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

// Units within this of a known value get its name (LinuxCNC's closeness).
const double UNITS_CLOSENESS = 0.0001;

// a is one of the known unit values b.
bool close_to(double a, double b)
{
    return std::fabs(a - b) < UNITS_CLOSENESS;
}

// Blanks separate words.
bool is_blank(char c)
{
    return c == ' ' || c == '\t';
}

} // namespace

// Words of a line.
std::vector<std::string> rsh_words(const std::string &line)
{
    std::vector<std::string> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) i++;
        size_t start = i;
        while (i < line.size() && !is_blank(line[i])) i++;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

// Text after the first n words.
std::string rsh_rest(const std::string &line, int n)
{
    size_t i = 0;
    for (int w = 0; w < n; w++) {
        while (i < line.size() && is_blank(line[i])) i++;
        while (i < line.size() && !is_blank(line[i])) i++;
    }
    while (i < line.size() && is_blank(line[i])) i++;
    size_t end = line.size();
    while (end > i && is_blank(line[end - 1])) end--;
    return line.substr(i, end - i);
}

// Upper-case copy.
std::string rsh_upper(std::string s)
{
    for (char &c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// Lower-case copy.
std::string rsh_lower(std::string s)
{
    for (char &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// on/off words.
int rsh_parse_on_off(const std::string &word)
{
    std::string w = rsh_lower(word);
    if (w == "on" || w == "1" || w == "true" || w == "yes") return 1;
    if (w == "off" || w == "0" || w == "false" || w == "no") return 0;
    return -1;
}

// Whole integers only.
bool rsh_parse_int(const std::string &word, long *out)
{
    if (word.empty()) return false;
    char *end;
    errno = 0;
    long v = strtol(word.c_str(), &end, 10);
    if (*end || errno) return false;
    *out = v;
    return true;
}

// Whole finite reals only.
bool rsh_parse_real(const std::string &word, double *out)
{
    if (word.empty()) return false;
    char *end;
    double v = strtod(word.c_str(), &end);
    if (*end || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

// Axis letter or number.
int rsh_parse_axis(const std::string &word)
{
    static const char letters[] = "XYZABCUVW";
    if (word.size() == 1) {
        char c = static_cast<char>(std::toupper(static_cast<unsigned char>(word[0])));
        for (int i = 0; i < EMCMOT_MAX_AXIS; i++)
            if (letters[i] == c) return i;
    }
    long n;
    if (rsh_parse_int(word, &n) && n >= -1 && n < EMCMOT_MAX_AXIS) return static_cast<int>(n);
    return -2;
}

// Linear units per mm as a name.
const char *rsh_linear_units_name(double u)
{
    if (close_to(u, 1.0 / 25.4)) return "INCH";
    if (close_to(u, 1.0)) return "MM";
    if (close_to(u, 0.1)) return "CM";
    return "CUSTOM";
}

// Angular units per degree as a name.
const char *rsh_angular_units_name(double u)
{
    if (close_to(u, 1.0)) return "DEG";
    if (close_to(u, M_PI / 180.0)) return "RAD";
    if (close_to(u, 100.0 / 90.0) || close_to(u, 0.9)) return "GRAD";
    return "CUSTOM";
}

// The interpreter's units as a name.
const char *rsh_program_units_name(int units)
{
    switch (units) {
    case 1: return "INCH";
    case 2: return "MM";
    case 3: return "CM";
    default: return "NONE";
    }
}

// Active G codes, feed and speed.
std::string rsh_program_codes(const EMC_TASK_STAT &t)
{
    std::string out;
    char buf[32];
    for (int i = 1; i < STATE_TAG_GCODES; i++) {
        int code = t.activeGCodes[i];
        if (code < 0) continue;
        if (code % 10) snprintf(buf, sizeof buf, "G%d.%d ", code / 10, code % 10);
        else snprintf(buf, sizeof buf, "G%d ", code / 10);
        out += buf;
    }
    snprintf(buf, sizeof buf, "F%.0f ", t.activeSettings[1]);
    out += buf;
    snprintf(buf, sizeof buf, "S%.0f", std::fabs(t.activeSettings[2]));
    return out + buf;
}

// Which line a UI shows while a program runs.
int rsh_program_line(const EMC_TASK_STAT &t, int start_line)
{
    if (start_line < 0 || t.readLine < start_line) return t.readLine;
    if (t.currentLine <= 0) return 0;
    if (t.motionLine > 0 && t.motionLine < t.currentLine) return t.motionLine;
    return t.currentLine;
}

// A real as %f.
std::string rsh_real(double v)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%f", v);
    return buf;
}
