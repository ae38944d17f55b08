// hooks_unit.cc: drives the interpreter with a HAL reader and a user-M handler installed, printing canon lines.
#include <cstdio>
#include <string>

#include "emc/rs274ngc/interp.hh"
#include "emc/rs274ngc/sai_canon.hh"

namespace {

// the test program: HAL values, EXISTS, M100-M199 with and without a program behind them
const char *PROGRAM =
    "(debug,x=#<_hal[axis.x.pos]>)\n"
    "#1 = [#<_hal[axis.x.pos]> * 2]\n"
    "#2 = EXISTS[#<_hal[axis.x.pos]>]\n"
    "#3 = EXISTS[#<_hal[no.such.pin]>]\n"
    "(debug,twice=#1 exists=#2 missing=#3)\n"
    "#4 = #<_hal[no.such.pin]>\n"
    "M101 P3 Q4.5\n"
    "M150\n"
    "M2\n";

// run PROGRAM to the end, reporting errors like rs274
void run(Interp &in)
{
    in.init();
    in.open_text("hooks.ngc", PROGRAM);
    for (;;) {
        InterpStatus st = in.execute_next();
        if (st == INTERP_EXIT) return;
        if (st == INTERP_ERROR) {
            printf("error: %s\n", in.error_text().c_str());
            if (in.at_end_of_file()) return;
        }
    }
}

} // namespace

// print where M<m> would be found
void show_user_m(const Interp &in, int m)
{
    std::string path = in.find_user_m(m);
    printf("M%d: %s\n", m, path.empty() ? "not found" : path.c_str());
}

// install the hooks and run; with an INI argument, show the M1nn search instead
int main(int argc, char **argv)
{
    std::string line;
    SaiCanon canon(stdout, &line);
    Interp in(canon);
    if (argc > 1) {
        if (!in.load_ini(argv[1])) return 1;
        for (int m : {101, 102, 103, 104, 199}) show_user_m(in, m);
        return 0;
    }
    in.set_var_file("/nonexistent/hooks.var");
    in.set_hal_reader([](const std::string &name, double &v) {
        printf("hal read %s\n", name.c_str());
        if (name != "axis.x.pos") return false;
        v = 1.25;
        return true;
    });
    in.set_user_m_handler([](int m, double p, double q) {
        printf("user M%d P%g Q%g -> %s\n", m, p, q, m == 101 ? "run" : "no program");
        return m == 101;
    });
    run(in);
    return 0;
}
