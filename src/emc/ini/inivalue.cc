// inivalue.cc: inivalue: typed INI lookups and listings for scripts (LinuxCNC's options, INI file as last argument).
#include "inifile.hh"
#include "ini_text.hh"

#include <cerrno>
#include <cfloat>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <getopt.h>
#include <string>

namespace {

const char usage_text[] =
    "Usage:\n"
    "    inivalue --var=<tag> [--sec=<sect>] [more-options...] <ini-file>\n"
    "    inivalue --sections <ini-file>\n"
    "    inivalue --variables [--sec=<sect>] [--content] [--prefix] <ini-file>\n"
    "Options:\n"
    "  -V|--var=str      the variable to look up\n"
    "  -S|--sec=str      only look in section 'str' (default: every section)\n"
    "  -N|--num=n        the n-th occurrence of the variable (default: 1)\n"
    "  -a|--all          every occurrence (from the --num-th on), one per line\n"
    "  -y|--type=x       i[nteger], u[nsigned], r[eal], s[tring] or b[oolean] (default: s)\n"
    "  -m|--minimum=val  smallest accepted value (types i, u and r; give --type first)\n"
    "  -M|--maximum=val  largest accepted value (types i, u and r; give --type first)\n"
    "  -b|--boolnum      print booleans as 1/0 instead of true/false\n"
    "  -B|--boolpy       print booleans as Python's True/False\n"
    "  -T|--tildeexpand  turn a leading ~/ of a string value into $HOME/\n"
    "  -q|--quiet        no message when the variable is not found\n"
    "  -e|--sections     list the section names\n"
    "  -o|--variables    list the variable names (of --sec, else of every section)\n"
    "  -c|--content      with -o: NAME=VALUE, the value escaped so that it reads back the same\n"
    "  -p|--prefix       with -o: put [SECTION] before each name (-c and -p imply -o)\n"
    "  -h|--help         this text\n"
    "Exit status: 0 found, 1 usage or file error (also after --help), 2 not found,\n"
    "3 conversion or range error.\n";

// Exit statuses.
enum { exit_found = 0, exit_usage = 1, exit_not_found = 2, exit_range = 3 };

// The value types of --type.
enum class ValueType { none, string, integer, unsigned_int, real, boolean };

// Everything the command line asks for.
struct Request {
    std::string var, sec, path;
    int num = -1;  // -1: not given
    ValueType type = ValueType::none;
    bool has_min = false, has_max = false;
    uint64_t min_int = 0, max_int = UINT64_MAX;  // --minimum/--maximum of i and u
    double min_real = -DBL_MAX, max_real = DBL_MAX;
    bool has_var = false, all = false, boolnum = false, boolpy = false, tilde = false, quiet = false;
    bool sections = false, variables = false, content = false, prefix = false;
};

// Print "error: <what>" on stderr.
void complain(const std::string &what)
{
    fprintf(stderr, "error: %s\n", what.c_str());
}

// Shortest text that reads back as the same double.
std::string shortest(double value)
{
    char buf[40];
    for (int digits = 1; digits <= 17; digits++) {
        snprintf(buf, sizeof buf, "%.*g", digits, value);
        if (strtod(buf, nullptr) == value) break;
    }
    return buf;
}

// An integer option value (sign, 0x/0o/0b prefix; negative values wrap as unsigned).
bool option_integer(const char *text, uint64_t &value)
{
    unsigned long long v = 0;
    IniConv conv = ini_parse_uint(text, v);
    if (conv == IniConv::invalid) complain(std::string("Invalid number converting '") + text + "'");
    if (conv == IniConv::trailing)
        complain(std::string("Trailing character(s) in numeric conversion of '") + text + "'");
    value = v;
    return conv == IniConv::ok;
}

// A real option value.
bool option_real(const char *text, double &value)
{
    IniConv conv = ini_parse_real(text, value);
    if (conv == IniConv::invalid) complain(std::string("Invalid floating point '") + text + "'");
    if (conv == IniConv::trailing)
        complain(std::string("Trailing character(s) in floating point of '") + text + "'");
    return conv == IniConv::ok;
}

// --type: the first letter decides.
bool option_type(Request &req, const char *text)
{
    switch (text[0] | 0x20) {
    case 'i': req.type = ValueType::integer; return true;
    case 'u': req.type = ValueType::unsigned_int; return true;
    case 'r': req.type = ValueType::real; return true;
    case 's': req.type = ValueType::string; return true;
    case 'b': req.type = ValueType::boolean; return true;
    }
    complain(std::string("Invalid type identifier '") + text[0] + "' accepted={i,u,b,s,r}");
    return false;
}

// --minimum / --maximum: parsed as the --type given before them.
bool option_limit(Request &req, const char *text, bool is_max)
{
    if (req.type == ValueType::none) {
        complain(std::string("Must first specify --type before ") + (is_max ? "maximum" : "minimum"));
        return false;
    }
    (is_max ? req.has_max : req.has_min) = true;
    if (req.type == ValueType::integer || req.type == ValueType::unsigned_int)
        return option_integer(text, is_max ? req.max_int : req.min_int);
    if (req.type == ValueType::real) return option_real(text, is_max ? req.max_real : req.min_real);
    return true;
}

// --num: a number >= 1 (any base strtol accepts).
bool option_num(Request &req, const char *text)
{
    char *end = nullptr;
    errno = 0;
    long n = strtol(text, &end, 0);
    bool ok = end != text && errno == 0 && (*end == '\0' || *end == ' ' || *end == '\t') && n >= 1 &&
              n <= 1000000000;
    if (!ok) complain(std::string("Invalid number '") + text + "' in --num argument");
    req.num = ok ? int(n) : -1;
    return ok;
}

// Apply one option; false when its argument is bad (already reported).
bool apply_option(Request &req, int id, const char *arg)
{
    switch (id) {
    case 'V': req.var = arg; req.has_var = true; return true;
    case 'S': req.sec = arg; return true;
    case 'N': return option_num(req, arg);
    case 'y': return option_type(req, arg);
    case 'm': return option_limit(req, arg, false);
    case 'M': return option_limit(req, arg, true);
    case 'a': req.all = true; return true;
    case 'b': req.boolnum = true; return true;
    case 'B': req.boolpy = true; return true;
    case 'T': req.tilde = true; return true;
    case 'q': req.quiet = true; return true;
    case 'e': req.sections = true; return true;
    case 'o': req.variables = true; return true;
    case 'c': req.content = true; return true;
    case 'p': req.prefix = true; return true;
    default: return false;  // getopt has printed what was wrong
    }
}

// Parse argv into a request; exits 1 on usage errors and after --help.
Request parse_command_line(int argc, char **argv)
{
    static const option longopts[] = {
        {"var", required_argument, nullptr, 'V'}, {"sec", required_argument, nullptr, 'S'},
        {"num", required_argument, nullptr, 'N'}, {"type", required_argument, nullptr, 'y'},
        {"minimum", required_argument, nullptr, 'm'}, {"maximum", required_argument, nullptr, 'M'},
        {"all", no_argument, nullptr, 'a'}, {"boolnum", no_argument, nullptr, 'b'},
        {"boolpy", no_argument, nullptr, 'B'}, {"tildeexpand", no_argument, nullptr, 'T'},
        {"quiet", no_argument, nullptr, 'q'}, {"sections", no_argument, nullptr, 'e'},
        {"variables", no_argument, nullptr, 'o'}, {"content", no_argument, nullptr, 'c'},
        {"prefix", no_argument, nullptr, 'p'}, {"help", no_argument, nullptr, 'h'},
        {nullptr, 0, nullptr, 0}};
    Request req;
    int id, bad = 0;
    while ((id = getopt_long(argc, argv, "V:S:N:y:m:M:abBTqeocph", longopts, nullptr)) != -1) {
        if (id == 'h') {
            fputs(usage_text, stdout);
            exit(exit_usage);
        }
        if (!apply_option(req, id, optarg)) bad++;
    }
    if ((req.content || req.prefix) && !req.has_var) req.variables = true;
    if (!bad && optind == argc) complain("Missing ini-file");
    if (!bad && argc - optind > 1) complain("Only one ini-file may be given, not '" + std::string(argv[optind + 1]) + "'");
    if (!bad && !req.has_var && !req.sections && !req.variables && optind == argc - 1)
        complain("No variable supplied (missing --var)");
    if (bad || optind != argc - 1 || (!req.has_var && !req.sections && !req.variables)) exit(exit_usage);
    req.path = argv[optind];
    return req;
}

// "[SEC]VAR" as messages quote the request.
std::string request_name(const Request &req)
{
    return "[" + req.sec + "]" + req.var;
}

// --sections and --variables listings.
int list_file(const IniFile &ini, const Request &req)
{
    if (req.sections) {
        for (const std::string &name : ini.Sections()) printf("%s\n", name.c_str());
        return exit_found;
    }
    if (!req.sec.empty() && !ini.HasSection(req.sec)) {
        if (!req.quiet) complain("Cannot find section '[" + req.sec + "]'");
        return exit_not_found;
    }
    for (const IniSection &sec : ini.AllSections()) {
        if (!req.sec.empty() && sec.name != req.sec) continue;
        for (const IniEntry &entry : sec.entries) {
            std::string line = req.prefix ? "[" + sec.name + "]" + entry.key : entry.key;
            if (req.content) line += "=" + ini_escape_value(entry.value);
            printf("%s\n", line.c_str());
        }
    }
    return exit_found;
}

// A boolean as the flags ask for it.
const char *bool_text(const Request &req, bool value)
{
    if (req.boolnum) return value ? "1" : "0";
    if (req.boolpy) return value ? "True" : "False";
    return value ? "true" : "false";
}

// The num-th value converted by --type without range checks (for --all); false when it does not
// convert (the library printed why).
bool typed_text(const IniFile &ini, const Request &req, int num, std::string &out)
{
    char buf[64];
    if (req.type == ValueType::integer) {
        std::optional<long long> v = ini.FindInt(req.var, req.sec, num);
        if (v) snprintf(buf, sizeof buf, "%lld", *v);
        return v && (out = buf, true);
    }
    if (req.type == ValueType::unsigned_int) {
        std::optional<unsigned long long> v = ini.FindUInt(req.var, req.sec, num);
        if (v) snprintf(buf, sizeof buf, "%llu", *v);
        return v && (out = buf, true);
    }
    if (req.type == ValueType::real) {
        std::optional<double> v = ini.FindReal(req.var, req.sec, num);
        if (v) snprintf(buf, sizeof buf, "%.15g", *v);
        return v && (out = buf, true);
    }
    if (req.type == ValueType::boolean) {
        std::optional<bool> v = ini.FindBool(req.var, req.sec, num);
        return v && (out = bool_text(req, *v), true);
    }
    out = ini.FindEntry(req.var, req.sec, num)->value;
    return true;
}

// Print a string value, tilde-expanded when asked; false when expansion is impossible.
bool print_string(const Request &req, const std::string &value)
{
    std::optional<std::string> text = req.tilde ? IniFile::TildeExpandStrict(value) : value;
    if (!text) {
        complain("Tilde expansion failed on '" + value + "'");
        return false;
    }
    printf("%s\n", text->c_str());
    return true;
}

// --all: every value from the --num-th on (values that do not convert are left out).
int print_all(const IniFile &ini, const Request &req)
{
    std::vector<std::string> values;
    std::string text;
    for (int num = 1; ini.FindEntry(req.var, req.sec, num); num++)
        if (typed_text(ini, req, num, text)) values.push_back(text);
    if (req.num > int(values.size())) {
        if (!req.quiet && values.empty()) complain("Cannot find any instance of '" + request_name(req) + "'");
        if (!req.quiet && !values.empty())
            complain("No instance " + std::to_string(req.num) + " or more of '" + request_name(req) + "'");
        return exit_not_found;
    }
    bool strings = req.type == ValueType::none || req.type == ValueType::string;
    for (size_t i = size_t(req.num < 1 ? 0 : req.num - 1); i < values.size(); i++) {
        if (!strings)
            printf("%s\n", values[i].c_str());
        else if (!print_string(req, values[i]))
            return exit_usage;
    }
    return exit_found;
}

// A signed integer value within --minimum/--maximum.
int print_integer(const IniFile &ini, const Request &req, int num, const std::string &raw)
{
    long long low = req.has_min ? (long long)req.min_int : INT64_MIN;
    long long high = req.has_max ? (long long)req.max_int : INT64_MAX;
    if (low > high) {
        complain("Invalid integer range min '" + std::to_string(low) + "' > max '" + std::to_string(high) + "'");
        return exit_range;
    }
    std::optional<long long> v = ini.FindInt(req.var, req.sec, num);
    if (!v || *v < low || *v > high) {
        complain("Invalid integer " + request_name(req) + "='" + raw + "' or out of range [" +
                 std::to_string(low) + "," + std::to_string(high) + "]");
        return exit_range;
    }
    printf("%lld\n", *v);
    return exit_found;
}

// An unsigned integer value within --minimum/--maximum.
int print_unsigned(const IniFile &ini, const Request &req, int num, const std::string &raw)
{
    unsigned long long low = req.has_min ? req.min_int : 0;
    unsigned long long high = req.has_max ? req.max_int : UINT64_MAX;
    if (low > high) {
        complain("Invalid unsigned range min '" + std::to_string(low) + "' > max '" + std::to_string(high) + "'");
        return exit_range;
    }
    std::optional<unsigned long long> v = ini.FindUInt(req.var, req.sec, num);
    if (!v || *v < low || *v > high) {
        complain("Invalid unsigned " + request_name(req) + "='" + raw + "' or out of range [" +
                 std::to_string(low) + "," + std::to_string(high) + "]");
        return exit_range;
    }
    printf("%llu\n", *v);
    return exit_found;
}

// A real value within --minimum/--maximum.
int print_real(const IniFile &ini, const Request &req, int num, const std::string &raw)
{
    if (req.min_real > req.max_real) {
        complain("Invalid real range min '" + shortest(req.min_real) + "' > max '" + shortest(req.max_real) + "'");
        return exit_range;
    }
    std::optional<double> v = ini.FindReal(req.var, req.sec, num);
    if (!v || *v < req.min_real || *v > req.max_real) {
        char range[80];
        snprintf(range, sizeof range, "[%g,%g]", req.min_real, req.max_real);
        complain("Invalid real " + request_name(req) + "='" + raw + "' or out of range " + range);
        return exit_range;
    }
    printf("%.15e\n", *v);
    return exit_found;
}

// The --num-th value of --var by --type.
int print_value(const IniFile &ini, const Request &req)
{
    int num = req.num < 1 ? 1 : req.num;
    const IniEntry *entry = ini.FindEntry(req.var, req.sec, num);
    if (!entry) {
        if (!req.quiet)
            complain("Cannot find instance " + std::to_string(num) + " of '" + request_name(req) + "'");
        return exit_not_found;
    }
    switch (req.type) {
    case ValueType::integer: return print_integer(ini, req, num, entry->value);
    case ValueType::unsigned_int: return print_unsigned(ini, req, num, entry->value);
    case ValueType::real: return print_real(ini, req, num, entry->value);
    case ValueType::boolean: {
        std::optional<bool> v = ini.FindBool(req.var, req.sec, num);
        if (!v) return exit_range;
        printf("%s\n", bool_text(req, *v));
        return exit_found;
    }
    default: return print_string(req, entry->value) ? exit_found : exit_usage;
    }
}

} // namespace

// Parse the command line, load the file and answer the request.
int main(int argc, char **argv)
{
    Request req = parse_command_line(argc, argv);
    IniFile ini;
    if (!ini.Open(req.path)) return exit_usage;
    int rc = req.sections || req.variables ? list_file(ini, req)
             : req.all                     ? print_all(ini, req)
                                           : print_value(ini, req);
    return fflush(stdout) == 0 ? rc : exit_usage;
}
