// varfile.cc: the parameter (.var) file: read at init, rewritten atomically (temp file + rename).
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

#include "interp.hh"

namespace {

// true for parameters that are always saved
bool persistent(int n)
{
    if ((n >= 5161 && n <= 5169) || (n >= 5181 && n <= 5189)) return true;
    if (n >= 5210 && n <= 5230) return true;
    return n >= 5241 && n <= 5390 && (n - 5241) % 20 < 10;
}

} // namespace

// Read the .var file; a missing file leaves everything 0. Lines that do not start with a
// number are skipped; a parameter number out of range, a value that is not a finite number
// or numbers out of order stop the initialisation (file:line in the message) and the file
// is left as it is.
void Interp::read_var_file()
{
    INTERP_FRAME();
    if (var_file_.empty()) return;   // no [RS274NGC]PARAMETER_FILE: nothing restored
    FILE *f = fopen(var_file_.c_str(), "r");
    if (!f) return;
    char line[512];
    int last = 0, lineno = 0;
    std::string error;
    while (error.empty() && fgets(line, sizeof line, f)) {
        lineno++;
        error = var_file_line(line, last);
        bool plain = error == "Parameter file out of order";  // LinuxCNC's text, kept as is
        if (!error.empty() && !plain)
            error = var_file_ + ":" + std::to_string(lineno) + ": " + error;
    }
    fclose(f);
    if (!error.empty()) {
        var_file_bad_ = true;
        throw InterpError(error);
    }
}

// One line of the .var file into the parameters; "" when fine or skipped, else what is wrong.
std::string Interp::var_file_line(const char *line, int &last)
{
    char *end;
    long n = strtol(line, &end, 10);
    if (end == line) return "";
    char *vend;
    double v = strtod(end, &vend);
    if (vend == end) return "parameter " + std::to_string(n) + " has no numeric value";
    if (!std::isfinite(v)) return "parameter " + std::to_string(n) + " is not a finite number";
    if (n < 1 || n >= PARAM_COUNT)
        return "parameter number " + std::to_string(n) + " out of range (1-" +
               std::to_string(PARAM_COUNT - 1) + ")";
    if (n <= last) return "Parameter file out of order";
    last = (int)n;
    s_.params[n] = v;
    in_var_file_.insert((int)n);
    return "";
}

// Write the .var file as <name>.new, keep <name>.bak as a hard link, then rename.
void Interp::write_var_file()
{
    INTERP_FRAME();
    if (var_file_bad_ || var_file_.empty()) return;
    std::string tmp = var_file_ + ".new", bak = var_file_ + ".bak";
    FILE *f = fopen(tmp.c_str(), "w");
    if (!f) return;
    for (int n = 1; n < PARAM_COUNT; n++) {
        if (!persistent(n) && !in_var_file_.count(n)) continue;
        fprintf(f, "%d\t%f\n", n, s_.params[n]);
    }
    if (fclose(f) != 0) {
        unlink(tmp.c_str());
        return;
    }
    unlink(bak.c_str());
    if (link(var_file_.c_str(), bak.c_str()) != 0) {
        fflush(stdout);
        fprintf(stderr, "link (updating variable file): %s\n", strerror(errno));
    }
    if (rename(tmp.c_str(), var_file_.c_str()) != 0) unlink(tmp.c_str());
}
