// rsh_format_test.cc: unit test of linuxcncrsh's text helpers (words, arguments, units, program codes and line).
#include <cmath>
#include <cstdio>

#include "rsh_format.hh"

namespace {

int failures = 0;

// Print a check's result; count failures.
void check(bool ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    if (!ok) failures++;
}

void words()
{
    std::vector<std::string> w = rsh_words("  set\tmdi  G0 X1 ");
    check(w.size() == 4 && w[0] == "set" && w[1] == "mdi" && w[3] == "X1", "words split on blanks and tabs");
    check(rsh_words("   ").empty(), "a blank line has no words");
    check(rsh_rest("set mdi  G0  X1 (move) ", 2) == "G0  X1 (move)", "rest keeps the inner text as typed");
    check(rsh_rest("set open", 2).empty(), "rest of a short line is empty");
    check(rsh_upper("joint_pos") == "JOINT_POS" && rsh_lower("MDI") == "mdi", "upper and lower case");
}

void arguments()
{
    check(rsh_parse_on_off("ON") == 1 && rsh_parse_on_off("yes") == 1 && rsh_parse_on_off("1") == 1 &&
              rsh_parse_on_off("True") == 1, "on words");
    check(rsh_parse_on_off("off") == 0 && rsh_parse_on_off("NO") == 0 && rsh_parse_on_off("0") == 0 &&
              rsh_parse_on_off("false") == 0, "off words");
    check(rsh_parse_on_off("maybe") == -1 && rsh_parse_on_off("") == -1, "neither on nor off");
    long n;
    double d;
    check(rsh_parse_int("-12", &n) && n == -12, "integer");
    check(!rsh_parse_int("12x", &n) && !rsh_parse_int("", &n) && !rsh_parse_int("1.5", &n), "not integers");
    check(rsh_parse_real("-0.25", &d) && d == -0.25 && rsh_parse_real("1e3", &d) && d == 1000, "reals");
    check(!rsh_parse_real("nan", &d) && !rsh_parse_real("inf", &d) && !rsh_parse_real("1,5", &d), "not reals");
    check(rsh_parse_axis("x") == 0 && rsh_parse_axis("W") == 8 && rsh_parse_axis("3") == 3 &&
              rsh_parse_axis("-1") == -1, "axes by letter, number and -1");
    check(rsh_parse_axis("9") == -2 && rsh_parse_axis("q") == -2 && rsh_parse_axis("xy") == -2 &&
              rsh_parse_axis("-2") == -2, "not axes");
}

void units()
{
    check(std::string(rsh_linear_units_name(1 / 25.4)) == "INCH", "1/25.4 per mm is INCH");
    check(std::string(rsh_linear_units_name(0.03937)) == "INCH", "0.03937 is close enough to an inch");
    check(std::string(rsh_linear_units_name(0.0395)) == "CUSTOM", "0.0395 is not");
    check(std::string(rsh_linear_units_name(1.0)) == "MM" && std::string(rsh_linear_units_name(0.1)) == "CM",
          "MM and CM");
    check(std::string(rsh_linear_units_name(2.0)) == "CUSTOM", "other linear units are CUSTOM");
    check(std::string(rsh_angular_units_name(1.0)) == "DEG" &&
              std::string(rsh_angular_units_name(M_PI / 180)) == "RAD" &&
              std::string(rsh_angular_units_name(100.0 / 90.0)) == "GRAD" &&
              std::string(rsh_angular_units_name(0.9)) == "GRAD" &&
              std::string(rsh_angular_units_name(3.0)) == "CUSTOM", "angular units");
    check(std::string(rsh_program_units_name(1)) == "INCH" && std::string(rsh_program_units_name(2)) == "MM" &&
              std::string(rsh_program_units_name(3)) == "CM" && std::string(rsh_program_units_name(0)) == "NONE",
          "program units");
}

void program()
{
    EMC_TASK_STAT t;
    const int codes[STATE_TAG_GCODES] = {7, 10, -1, 170, 400, 210, 900, 940, 590, 430, 990, 641, -1, 960, 911, 70, 923};
    for (int i = 0; i < STATE_TAG_GCODES; i++) t.activeGCodes[i] = codes[i];
    t.activeSettings[1] = 12.5;
    t.activeSettings[2] = -1200;
    std::string got = rsh_program_codes(t);
    printf("     %s\n", got.c_str());
    check(got == "G1 G17 G40 G21 G90 G94 G59 G43 G99 G64.1 G96 G91.1 G7 G92.3 F12 S1200",
          "program codes skip the sequence number and unused slots");
    t.readLine = 10;
    t.currentLine = 9;
    t.motionLine = 4;
    check(rsh_program_line(t, 0) == 4, "the motion line while it lags behind");
    t.motionLine = 9;
    check(rsh_program_line(t, 0) == 9, "the issued line once motion caught up");
    check(rsh_program_line(t, 20) == 10 && rsh_program_line(t, -1) == 10, "read line before a start line");
    t.currentLine = 0;
    check(rsh_program_line(t, 0) == 0, "0 before anything was issued");
    check(rsh_real(-1.5) == "-1.500000", "reals print with six decimals");
}

} // namespace

int main()
{
    words();
    arguments();
    units();
    program();
    printf("%d failures\n", failures);
    return failures ? 1 : 0;
}
