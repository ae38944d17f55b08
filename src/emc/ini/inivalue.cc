// inivalue.cc: inivalue: typed INI lookups and listings for scripts (long options, INI file as last argument).
#include "inifile.hh"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <getopt.h>
#include <string>

namespace {

const char usage_text[] =
    "Usage: inivalue [options] INIFILE\n"
    "  --var=NAME        variable to print\n"
    "  --sec=SECTION     section to search (default: all sections)\n"
    "  --num=N           print the N-th instance (default 1)\n"
    "  --all             print every instance, one per line\n"
    "  --type=i|u|r|s|b  signed, unsigned, real, string (default) or boolean\n"
    "  --minimum=V       smallest accepted number (i, u, r)\n"
    "  --maximum=V       largest accepted number (i, u, r)\n"
    "  --boolnum         print booleans as 1/0 (default true/false)\n"
    "  --boolpy          print booleans as True/False\n"
    "  --tildeexpand     turn a leading ~/ of a string into $HOME/\n"
    "  --quiet           no error messages\n"
    "  --sections        list the section names\n"
    "  --variables       list the variable names (of --sec, else of all sections)\n"
    "  --content         print NAME=VALUE lines (of --sec, else of all sections)\n"
    "  --prefix          print values as [SECTION]NAME=VALUE\n"
    "  --help            show this text\n"
    "Exit status: 0 found, 1 usage or file error, 2 not found, 3 conversion or range error.\n";

// Everything the command line asks for.
struct Request {
    std::string var, sec, path, min_text, max_text;
    int num = 1;
    char type = 's';
    bool all = false, boolnum = false, boolpy = false, tilde = false, quiet = false;
    bool sections = false, variables = false, content = false, prefix = false;
    bool has_var = false, has_min = false, has_max = false;
};

// Print "error: <what>" unless quiet.
void complain(const Request &req, const std::string &what)
{
    if (!req.quiet) fprintf(stderr, "error: %s\n", what.c_str());
}

// True when text is a complete real number.
bool is_number(const std::string &text)
{
    char *end = nullptr;
    strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0';
}

// Apply one parsed option to the request; false on a bad argument.
bool apply_option(Request &req, int id, const char *arg)
{
    std::string text = arg ? arg : "";
    switch (id) {
    case 'v': req.var = text; req.has_var = true; return true;
    case 's': req.sec = text; return true;
    case 'n': {
        char *end = nullptr;
        long n = strtol(text.c_str(), &end, 10);
        req.num = int(n);
        return !text.empty() && *end == '\0' && n >= 1 && n <= 1000000000;
    }
    case 't':
        req.type = text.size() == 1 ? text[0] : '?';
        return std::string("iursb").find(req.type) != std::string::npos;
    case 'm': req.min_text = text; req.has_min = true; return is_number(text);
    case 'M': req.max_text = text; req.has_max = true; return is_number(text);
    case 'a': req.all = true; return true;
    case 'B': req.boolnum = true; return true;
    case 'P': req.boolpy = true; return true;
    case 'T': req.tilde = true; return true;
    case 'q': req.quiet = true; return true;
    case 'S': req.sections = true; return true;
    case 'V': req.variables = true; return true;
    case 'C': req.content = true; return true;
    case 'p': req.prefix = true; return true;
    default: return false;
    }
}

// Parse argv into a request; exits 1 on usage errors and after --help.
Request parse_command_line(int argc, char **argv)
{
    static const option longopts[] = {
        {"var", required_argument, nullptr, 'v'}, {"sec", required_argument, nullptr, 's'},
        {"num", required_argument, nullptr, 'n'}, {"type", required_argument, nullptr, 't'},
        {"minimum", required_argument, nullptr, 'm'}, {"maximum", required_argument, nullptr, 'M'},
        {"all", no_argument, nullptr, 'a'}, {"boolnum", no_argument, nullptr, 'B'},
        {"boolpy", no_argument, nullptr, 'P'}, {"tildeexpand", no_argument, nullptr, 'T'},
        {"quiet", no_argument, nullptr, 'q'}, {"sections", no_argument, nullptr, 'S'},
        {"variables", no_argument, nullptr, 'V'}, {"content", no_argument, nullptr, 'C'},
        {"prefix", no_argument, nullptr, 'p'}, {"help", no_argument, nullptr, 'h'},
        {nullptr, 0, nullptr, 0}};
    Request req;
    int id;
    opterr = 0;
    while ((id = getopt_long(argc, argv, ":", longopts, nullptr)) != -1) {
        if (id == '?' || id == ':') {
            fprintf(stderr, "inivalue: %s '%s' (try --help)\n",
                    id == '?' ? "Invalid option" : "Missing argument to", argv[optind - 1]);
            exit(1);
        }
        if (id == 'h') {
            fputs(usage_text, stdout);
            exit(1);
        }
        if (!apply_option(req, id, optarg)) {
            const char *name = id == 'n' ? "num" : id == 't' ? "type" : id == 'm' ? "minimum" : "maximum";
            fprintf(stderr, "error: Invalid %s '%s' in --%s argument\n",
                    id == 'n' ? "number" : "value", optarg, name);
            exit(1);
        }
    }
    if (optind != argc - 1) {
        fprintf(stderr, "inivalue: exactly one INI file must be given (try --help)\n");
        exit(1);
    }
    req.path = argv[optind];
    return req;
}

// Print the section names, the variable names or NAME=VALUE lines.
int list_file(const IniFile &ini, const Request &req)
{
    if (req.sections) {
        for (const std::string &name : ini.Sections()) printf("%s\n", name.c_str());
        return 0;
    }
    if (!req.sec.empty() && !ini.HasSection(req.sec)) {
        complain(req, "Cannot find section '[" + req.sec + "]'");
        return 2;
    }
    for (const auto &kv : ini.Variables(req.sec)) {
        if (req.variables)
            printf("%s\n", kv.first.c_str());
        else
            printf("%s=%s\n", kv.first.c_str(), kv.second.c_str());
    }
    return 0;
}

// Check a number against --minimum/--maximum; false (diagnosed) when outside.
bool in_range(const Request &req, const IniEntry &entry, double value)
{
    double low = req.has_min ? strtod(req.min_text.c_str(), nullptr) : -HUGE_VAL;
    double high = req.has_max ? strtod(req.max_text.c_str(), nullptr) : HUGE_VAL;
    if (value >= low && value <= high) return true;
    complain(req, "Value out of range [" + entry.section + "]" + entry.key + "='" + entry.value +
                      "' (minimum " + (req.has_min ? req.min_text : "none") + ", maximum " +
                      (req.has_max ? req.max_text : "none") + ")");
    return false;
}

// Format one entry by --type; returns 0, or 3 for a conversion or range error.
int format_value(const IniFile &ini, const Request &req, int num, std::string &out)
{
    const IniEntry *entry = ini.FindEntry(req.var, req.sec, num);
    char buf[64];
    if (req.type == 'i' || req.type == 'u' || req.type == 'r') {
        std::optional<long long> i;
        std::optional<unsigned long long> u;
        std::optional<double> r;
        if (req.type == 'i' && (i = ini.FindInt(req.var, req.sec, num)))
            snprintf(buf, sizeof buf, "%lld", *i);
        else if (req.type == 'u' && (u = ini.FindUInt(req.var, req.sec, num)))
            snprintf(buf, sizeof buf, "%llu", *u);
        else if (req.type == 'r' && (r = ini.FindReal(req.var, req.sec, num)))
            snprintf(buf, sizeof buf, "%.15e", *r);
        else
            return 3;
        double value = i ? double(*i) : u ? double(*u) : *r;
        if (!in_range(req, *entry, value)) return 3;
        out = buf;
    } else if (req.type == 'b') {
        std::optional<bool> b = ini.FindBool(req.var, req.sec, num);
        if (!b) return 3;
        out = req.boolnum ? (*b ? "1" : "0") : req.boolpy ? (*b ? "True" : "False")
                                                          : (*b ? "true" : "false");
    } else {
        out = req.tilde ? IniFile::TildeExpand(entry->value) : entry->value;
    }
    if (req.prefix) out = "[" + entry->section + "]" + entry->key + "=" + out;
    return 0;
}

// Print the requested instance(s) of --var.
int print_values(IniFile &ini, const Request &req)
{
    ini.SetQuiet(req.quiet);
    int first = req.all ? 1 : req.num;
    if (!ini.FindEntry(req.var, req.sec, first)) {
        complain(req, "Cannot find instance " + std::to_string(first) + " of '[" + req.sec + "]" +
                          req.var + "'");
        return 2;
    }
    for (int num = first; ini.FindEntry(req.var, req.sec, num); num++) {
        std::string text;
        int rc = format_value(ini, req, num, text);
        if (rc) return rc;
        printf("%s\n", text.c_str());
        if (!req.all) break;
    }
    return 0;
}

} // namespace

// Parse the command line, load the file and answer the request.
int main(int argc, char **argv)
{
    Request req = parse_command_line(argc, argv);
    if (!req.has_var && !req.sections && !req.variables && !req.content) {
        fprintf(stderr, "inivalue: No variable supplied (missing --var)\n");
        return 1;
    }
    IniFile ini;
    if (!ini.Open(req.path)) return 1;
    int rc = req.has_var ? print_values(ini, req) : list_file(ini, req);
    return fflush(stdout) == 0 ? rc : 1;
}
