// sub_reload_unit.cc: one interpreter runs a program calling a SUBROUTINE_PATH file twice; the file is
// rewritten in between and the second run must use the new text (files are kept only while unchanged).
#include <cstdio>
#include <string>

#include "emc/rs274ngc/interp.hh"
#include "emc/rs274ngc/sai_canon.hh"

namespace {

// write text to path
bool write_file(const std::string &path, const char *text)
{
    FILE *f = fopen(path.c_str(), "w");
    if (!f) return false;
    fputs(text, f);
    return fclose(f) == 0;
}

// run "o<greet> call" twice and M2
void run(Interp &in)
{
    in.open_text("main.ngc", "o<greet> call\no<greet> call\nM2\n");
    for (;;) {
        InterpStatus st = in.execute_next();
        if (st == INTERP_EXIT) return;
        if (st == INTERP_ERROR) {
            printf("error: %s\n", in.error_text().c_str());
            return;
        }
    }
}

} // namespace

// argv[1]: a scratch directory
int main(int argc, char **argv)
{
    if (argc < 2) return 2;
    std::string dir = argv[1], ini = dir + "/test.ini", sub = dir + "/greet.ngc";
    std::string ini_text = "[RS274NGC]\nSUBROUTINE_PATH = " + dir + "\n";
    if (!write_file(ini, ini_text.c_str())) return 1;
    if (!write_file(sub, "o<greet> sub\n(debug,first version)\no<greet> endsub\nM2\n")) return 1;
    std::string line;
    SaiCanon canon(stdout, &line);
    Interp in(canon);
    if (!in.load_ini(ini)) return 1;
    in.set_var_file(dir + "/none.var");
    in.init();
    run(in);
    if (!write_file(sub, "o<greet> sub\n(debug,second version, a longer file)\no<greet> endsub\nM2\n")) return 1;
    run(in);
    return 0;
}
