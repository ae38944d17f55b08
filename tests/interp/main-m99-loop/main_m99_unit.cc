// main_m99_unit.cc: runs a program ending in M99 once as rs274 does and once with the main-program
// loop task enables, printing the canon calls.
#include <cstdio>
#include <string>

#include "emc/rs274ngc/interp.hh"
#include "emc/rs274ngc/sai_canon.hh"

namespace {

// counts its passes in #1 (a global, not reset by the restart), ends itself on the third
const char *PROGRAM =
    "%\n"
    "#1 = [#1 + 1]\n"
    "(debug,pass #1)\n"
    "o10 if [#1 GE 3]\n"
    "  m2\n"
    "o10 endif\n"
    "g0 x#1\n"
    "g91\n"
    "m99\n"
    "%\n";

// run PROGRAM to its end; returns 1 on an interpreter error
int run(bool loop)
{
    std::string line;
    SaiCanon canon(stdout, &line);
    Interp in(canon);
    in.set_var_file("/nonexistent/main-m99.var");
    in.set_loop_on_main_m99(loop);
    in.init();
    in.open_text("main-m99.ngc", PROGRAM);
    for (int n = 0; n < 1000; n++) {
        InterpStatus st = in.execute_next();
        if (st == INTERP_EXIT) return 0;
        if (st == INTERP_ERROR) {
            printf("error: %s\n", in.error_text().c_str());
            return 1;
        }
    }
    printf("error: the program did not end\n");
    return 1;
}

} // namespace

int main()
{
    printf("--- rs274: M99 ends the main program\n");
    int bad = run(false);
    printf("--- task: M99 restarts the main program\n");
    bad |= run(true);
    return bad;
}
