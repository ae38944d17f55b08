// rsh_format.hh: linuxcncrsh's pure text helpers: words, on/off, numbers, axis names, unit names, program codes and line.
#ifndef RSH_FORMAT_HH
#define RSH_FORMAT_HH

#include <string>
#include <vector>

#include "emc_nml.hh"

// Split a request line into words (blanks and tabs separate them).
std::vector<std::string> rsh_words(const std::string &line);
// The text after the first n words of line, leading blanks removed ("set mdi g0 x1" with
// n = 2 gives "g0 x1").
std::string rsh_rest(const std::string &line, int n);
// Upper / lower case copies.
std::string rsh_upper(std::string s);
std::string rsh_lower(std::string s);

// on/1/true/yes -> 1, off/0/false/no -> 0 (any case), anything else -1.
int rsh_parse_on_off(const std::string &word);
// A whole decimal integer; false when word is not one.
bool rsh_parse_int(const std::string &word, long *out);
// A whole finite real number; false when word is not one.
bool rsh_parse_real(const std::string &word, double *out);
// An axis: a letter XYZABCUVW (any case) or 0..8 gives its index, -1 stays -1 ("all");
// -2 when word names no axis.
int rsh_parse_axis(const std::string &word);

// Unit names from units per mm / per degree, as LinuxCNC guesses them:
// INCH (1/25.4), MM (1), CM (0.1), else CUSTOM; DEG (1), RAD (pi/180), GRAD (100/90, or
// 0.9 as the INI library states grads), else CUSTOM.
const char *rsh_linear_units_name(double units_per_mm);
const char *rsh_angular_units_name(double units_per_degree);
// The interpreter's program units (1 in, 2 mm, 3 cm): INCH, MM, CM, else NONE.
const char *rsh_program_units_name(int program_units);

// "G80 G17 ... F0 S0": the active G codes (value/10, with the decimal when value % 10),
// skipping the sequence number and unused slots, then the feed and speed.
std::string rsh_program_codes(const EMC_TASK_STAT &t);
// The program line to show: the line motion executes when it lags behind the one task
// issued, else the one issued, else the last one read (before a run from start_line).
int rsh_program_line(const EMC_TASK_STAT &t, int start_line);

// printf("%f") of a value, as every position and time reply uses.
std::string rsh_real(double v);

#endif
