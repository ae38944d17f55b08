// inivar.cc: inivar: print the value of one INI variable (-var KEY [-sec S] [-num N] [-ini F] [-tildeexpand]).
#include "inifile.hh"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

namespace {

// The parsed command line: option name -> argument ("" for -tildeexpand).
using Options = std::map<std::string, std::string>;

// Print "inivar: <what>" and exit 1.
[[noreturn]] void usage_error(const std::string &what)
{
    fprintf(stderr, "inivar: %s\n", what.c_str());
    exit(1);
}

const char usage_text[] =
    "Usage: inivar -var VARIABLE [-sec SECTION] [-num N] [-ini INIFILE] [-tildeexpand]\n"
    "Prints the N-th (default first) value of VARIABLE in SECTION (default: any section) of\n"
    "INIFILE (default emc.ini). -tildeexpand turns a leading ~/ into $HOME/.\n"
    "Exit status: 0 found, 1 usage or file error, 2 not found. See also inivalue.\n";

// Parse the single-dash options; every problem is fatal.
Options parse_options(int argc, char **argv)
{
    if (argc == 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-help") || !strcmp(argv[1], "-h"))) {
        fputs(usage_text, stdout);
        exit(0);
    }
    static const char *const with_arg[] = {"-var", "-sec", "-num", "-ini"};
    Options opts;
    for (int i = 1; i < argc; i++) {
        std::string opt = argv[i];
        bool takes_arg = false;
        for (const char *name : with_arg) takes_arg = takes_arg || opt == name;
        if (!takes_arg && opt != "-tildeexpand") usage_error("Invalid option '" + opt + "'");
        if (opts.count(opt)) usage_error("Duplicate " + opt + " option");
        if (takes_arg && i + 1 >= argc) usage_error("Missing argument to " + opt);
        opts[opt] = takes_arg ? argv[++i] : "";
    }
    return opts;
}

// The -num argument: a decimal number >= 1; exits 1 otherwise.
int instance_number(const Options &opts)
{
    auto found = opts.find("-num");
    if (found == opts.end()) return 1;
    const std::string &text = found->second;
    char *end = nullptr;
    long n = strtol(text.c_str(), &end, 10);
    bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || *end || n < 1 || n > 1000000000) {
        fprintf(stderr, "error: Invalid number '%s' in --num argument\n", text.c_str());
        exit(1);
    }
    return int(n);
}

} // namespace

// Look the variable up and print it; exit 0 found, 2 not found, 1 usage or file errors.
int main(int argc, char **argv)
{
    Options opts = parse_options(argc, argv);
    if (!opts.count("-var")) usage_error("No variable supplied (missing -var)");
    int num = instance_number(opts);
    std::string section = opts.count("-sec") ? opts["-sec"] : "";
    IniFile ini;
    if (!ini.Open(opts.count("-ini") ? opts["-ini"] : "emc.ini")) return 1;
    std::optional<std::string> value = ini.Find(opts["-var"], section, num);
    if (!value) {
        fprintf(stderr, "error: Cannot find instance %d of '[%s]%s'\n", num, section.c_str(),
                opts["-var"].c_str());
        return 2;
    }
    std::string text = opts.count("-tildeexpand") ? IniFile::TildeExpand(*value) : *value;
    fwrite(text.data(), 1, text.size(), stdout);
    putchar('\n');
    return fflush(stdout) == 0 ? 0 : 1;
}
