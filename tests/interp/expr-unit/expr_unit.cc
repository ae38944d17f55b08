// expr_unit.cc: unit test of the expression evaluator and number formatting: one case per input line.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include "emc/rs274ngc/interp.hh"
#include "emc/rs274ngc/sai_canon.hh"

// Evaluate "[expr]" lines (after normalizing like a G-code line) and print value or error.
static void eval_case(Interp &in, const std::string &text)
{
    Block b;
    try {
        in.parse_line("#1000=" + text, b);
        if (b.num_assign.empty()) throw InterpError("no value");
        printf("%s = %.6f\n", text.c_str(), b.num_assign[0].second);
    } catch (const InterpError &e) {
        printf("%s : %s\n", text.c_str(), e.what());
    }
}

// Compare format_fixed4 with printf("%.4f") on many values; print the mismatch count.
static void check_format()
{
    int bad = 0;
    srand(1);
    for (int i = 0; i < 200000; i++) {
        double scale = (i % 7 == 0) ? 1e-4 : (i % 7 == 1) ? 1e6 : 100.0;
        double v = ((double)rand() / RAND_MAX - 0.5) * scale;
        if (i % 5 == 0) v = (double)(rand() % 200000 - 100000) / 20000.0;
        if (i % 11 == 0) v = (rand() % 100000) * 0.00005;
        char a[64], b[64];
        snprintf(a, sizeof a, "%.4f", v);
        format_fixed4(b, v);
        if (strcmp(a, b) != 0 && bad++ < 5) printf("format mismatch %s %s\n", a, b);
    }
    const double edge[] = {0.00005, 0.00015, -0.0, -0.00001, 1e30, 0.5, 999999.99995};
    for (double v : edge) {
        char a[64], b[64];
        snprintf(a, sizeof a, "%.4f", v);
        format_fixed4(b, v);
        if (strcmp(a, b) != 0) bad++;
    }
    printf("format mismatches: %d\n", bad);
}

// Entry point: cases on stdin.
int main()
{
    std::string line;
    SaiCanon canon(nullptr, &line);
    Interp in(canon);
    std::string text;
    while (std::getline(std::cin, text)) {
        if (text.empty() || text[0] == ';') continue;
        eval_case(in, text);
    }
    check_format();
    return 0;
}
