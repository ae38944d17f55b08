// varfile.cc: the parameter (.var) file: read at init, rewritten atomically (temp file + rename).
#include <cerrno>
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

// Read the .var file; a missing file leaves everything 0; out of order is fatal.
void Interp::read_var_file()
{
    INTERP_FRAME();
    if (var_file_.empty()) return;
    FILE *f = fopen(var_file_.c_str(), "r");
    if (!f) return;
    char line[512];
    int last = 0;
    while (fgets(line, sizeof line, f)) {
        char *end;
        long n = strtol(line, &end, 10);
        if (end == line) continue;
        char *vend;
        double v = strtod(end, &vend);
        if (vend == end) continue;
        if (n < 1 || n >= PARAM_COUNT) continue;
        if (n <= last) {
            fclose(f);
            throw InterpError("Parameter file out of order");
        }
        last = (int)n;
        s_.params[n] = v;
        in_var_file_.insert((int)n);
    }
    fclose(f);
}

// Write the .var file as <name>.new, keep <name>.bak as a hard link, then rename.
void Interp::write_var_file()
{
    INTERP_FRAME();
    if (var_file_.empty()) return;
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
