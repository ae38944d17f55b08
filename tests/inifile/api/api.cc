// api.cc: unit test of the INI library's C++ and C APIs (typed reads, enumerations, errors); prints results.
#include "inifile.h"
#include "inifile.hh"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// Print an optional value or "none".
template <typename T>
void show(const char *what, const std::optional<T> &value, const char *fmt)
{
    printf("%s: ", what);
    if (value)
        printf(fmt, *value);
    else
        printf("none");
    printf("\n");
    fflush(stdout);
}

// Typed lookups of the [INT] [REAL] [BOOL] [ENUM] sections.
void typed(const IniFile &ini)
{
    for (const char *k : {"DEC", "NEG", "HEX", "OCT", "BIN", "PLUS", "BLANK_TAIL", "ATTACHED", "NONE",
                          "BIG", "MINUS1", "MISSING"})
        show((std::string("int ") + k).c_str(), ini.FindInt(k, "INT"), "%lld");
    show("uint MINUS1", ini.FindUInt("MINUS1", "INT"), "%llu");
    show("uint NEG", ini.FindUInt("NEG", "INT"), "%llu");
    for (const char *k : {"SCI", "HEX", "PI", "ATTACHED", "NONE", "NEG"})
        show((std::string("real ") + k).c_str(), ini.FindReal(k, "REAL"), "%g");
    for (const char *k : {"T1", "T2", "T3", "T4", "F1", "F2", "F3", "F4", "BAD"}) {
        std::optional<bool> b = ini.FindBool(k, "BOOL");
        printf("bool %s: %s\n", k, b ? (*b ? "true" : "false") : "none");
        fflush(stdout);
    }
    for (const char *k : {"MM", "INCH", "CM"})
        show((std::string("linear ") + k).c_str(), ini.FindLinearUnits(k, "ENUM"), "%.9f");
    for (const char *k : {"DEG", "RAD", "GON"})
        show((std::string("angular ") + k).c_str(), ini.FindAngularUnits(k, "ENUM"), "%.9f");
    for (const char *k : {"LIN", "ANG", "BADTYPE"})
        show((std::string("joint ") + k).c_str(), ini.FindJointType(k, "ENUM"), "%d");
}

// FindAll, Sections, Variables, HasSection, FindEntry.
void listing(const IniFile &ini)
{
    printf("findall APP:");
    for (const std::string &v : ini.FindAll("APP", "LIST")) printf(" %s", v.c_str());
    printf("\nfindall APP any section: %zu\nsections:", ini.FindAll("APP").size());
    for (const std::string &s : ini.Sections()) printf(" %s", s.c_str());
    printf("\nvariables LIST:");
    for (const auto &kv : ini.Variables("LIST")) printf(" %s=%s", kv.first.c_str(), kv.second.c_str());
    printf("\nvariables NOPE: %zu\n", ini.Variables("NOPE").size());
    printf("hassection LIST %d NOPE %d\n", ini.HasSection("LIST"), ini.HasSection("NOPE"));
    const IniEntry *e = ini.FindEntry("APP", "LIST", 3);
    printf("entry APP 3: %s %s:%d [%s]\n", e->value.c_str(), e->file.c_str(), e->line,
           e->section.c_str());
    printf("find num 0: %s\n", ini.Find("APP", "LIST", 0) ? "found" : "none");
    fflush(stdout);
}

// Print the status of a C lookup and the value it stored.
void c_result(const char *what, int status, const std::string &value)
{
    printf("%s: %d %s\n", what, status, status == 0 ? value.c_str() : "-");
    fflush(stdout);
}

// The handle-based C API on the same file.
void c_api(const char *path)
{
    ini_file_t *ini = ini_open(path);
    long long i = 0;
    double d = 0;
    int b = 0, st;
    unsigned long long u = 0;
    printf("c find APP 2: %s\n", ini_find(ini, "APP", "LIST", 2));
    printf("c find missing: %s\n", ini_find(ini, "NOPE", NULL, 1) ? "found" : "NULL");
    st = ini_find_int(ini, "DEC", "INT", 1, &i);
    c_result("c int DEC", st, std::to_string(i));
    st = ini_find_int(ini, "NONE", "INT", 1, &i);
    c_result("c int NONE (-EINVAL)", st == -EINVAL, "");
    st = ini_find_int(ini, "MISSING", "INT", 1, &i);
    c_result("c int MISSING (-ENOENT)", st == -ENOENT, "");
    st = ini_find_uint(ini, "HEX", "INT", 1, &u);
    c_result("c uint HEX", st, std::to_string(u));
    st = ini_find_double(ini, "SCI", NULL, 1, &d);
    c_result("c double SCI", st, std::to_string(d));
    st = ini_find_bool(ini, "T2", "BOOL", 1, &b);
    c_result("c bool T2", st, std::to_string(b));
    ini_close(ini);
    printf("ini_open missing: %s\n", ini_open("no-such.ini") ? "handle" : "NULL");
}

// LinuxCNC's path-based lookups.
void path_api(const char *path)
{
    char buf[64], tiny[3];
    rtapi_s64 i = 0;
    rtapi_u64 u = 0;
    int n = 0, st;
    bool b = false;
    double d = 0;
    st = iniFindString(path, "OTHER", "LIST", buf, sizeof buf);
    c_result("iniFindString OTHER", st, buf);
    c_result("iniFindString too small (-ENOSPC)", iniFindString(path, "APP", NULL, tiny, sizeof tiny) == -ENOSPC, "");
    st = iniFindSInt(path, "NEG", "INT", &i);
    c_result("iniFindSInt NEG", st, std::to_string(i));
    st = iniFindUInt(path, "MINUS1", "INT", &u);
    c_result("iniFindUInt MINUS1", st, std::to_string(u));
    st = iniFindInt(path, "HEX", "INT", &n);
    c_result("iniFindInt HEX", st, std::to_string(n));
    c_result("iniFindInt BIG (-ENOENT)", iniFindInt(path, "BIG", "INT", &n) == -ENOENT, "");
    st = iniFindDouble(path, "PI", "REAL", &d);
    c_result("iniFindDouble PI", st, std::to_string(d));
    st = iniFindBool(path, "T3", "", &b);
    c_result("iniFindBool T3", st, std::to_string(b));
    c_result("iniFindBool missing section (-ENOENT)", iniFindBool(path, "T3", "NOPE", &b) == -ENOENT, "");
    c_result("iniFindBool no file (-EINVAL)", iniFindBool("no-such.ini", "T3", NULL, &b) == -EINVAL, "");
    c_result("iniFindString NULL tag (-EINVAL)", iniFindString(path, NULL, NULL, buf, sizeof buf) == -EINVAL, "");
    setenv("HOME", "/home/x", 1);
    st = TildeExpansion("~/a.ini", buf, sizeof buf);
    c_result("TildeExpansion", st, buf);
    c_result("TildeExpansion too long (-ENOSPC)", TildeExpansion("~/a.ini", tiny, sizeof tiny) == -ENOSPC, "");
    unsetenv("HOME");
    c_result("TildeExpansion no HOME (-ENOENT)", TildeExpansion("~/a.ini", buf, sizeof buf) == -ENOENT, "");
}

// Open failures: a syntax error and a missing file.
void failures(const char *broken_path)
{
    IniFile broken;
    bool opened = broken.Open(broken_path);
    printf("open broken: %d error: %s\n", opened, broken.ErrorText().c_str());
    printf("broken lookup: %s\n", broken.Find("X") ? "found" : "none");
    IniFile missing;
    opened = missing.Open("no-such.ini");
    printf("open missing: %d error: %s\n", opened, missing.ErrorText().c_str());
}

} // namespace

// Run every check on typed.ini (argv[1]) and a broken file (argv[2]).
int main(int argc, char **argv)
{
    if (argc != 3) return 2;
    setvbuf(stdout, nullptr, _IOLBF, 0);  // keep stdout and stderr lines in order
    IniFile ini(argv[1]);
    printf("open: %d\n", ini.IsOpen());
    typed(ini);
    listing(ini);
    c_api(argv[1]);
    path_api(argv[1]);
    failures(argv[2]);
    return 0;
}
