// ini_convert.cc: trimming, identifier checks and the typed conversions (int, uint, real, bool) of INI values.
#include "ini_text.hh"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <locale.h>
#include <strings.h>

namespace {

// Whitespace as stripped around lines and values.
bool is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Classify what follows a number: nothing or a blank is fine, anything else is trailing text.
IniConv tail_state(const char *end)
{
    return (*end == '\0' || is_blank(*end)) ? IniConv::ok : IniConv::trailing;
}

// Parse the magnitude of an integer (after the sign) with its prefix; end points past the digits.
bool parse_magnitude(const char *p, unsigned long long &mag, const char **end, bool &overflow)
{
    int base = 10;
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X') && isxdigit((unsigned char)p[2])) {
        base = 16;
        p += 2;
    } else if (p[0] == '0' && (p[1] == 'o' || p[1] == 'O') && p[2] >= '0' && p[2] <= '7') {
        base = 8;
        p += 2;
    } else if (p[0] == '0' && (p[1] == 'b' || p[1] == 'B') && (p[2] == '0' || p[2] == '1')) {
        base = 2;
        p += 2;
    }
    if (!isdigit((unsigned char)*p) && !(base == 16 && isxdigit((unsigned char)*p))) return false;
    char *stop = nullptr;
    errno = 0;
    mag = strtoull(p, &stop, base);
    overflow = errno == ERANGE;
    *end = stop;
    return true;
}

// An integer's text split into sign and magnitude.
struct IntText {
    bool negative = false;
    unsigned long long mag = 0;
    const char *end = nullptr;  // past the digits
    bool overflow = false;      // the magnitude does not fit 64 bits
};

// Parse an optional sign and an integer magnitude; false when no digits follow.
bool parse_integer(const std::string &text, IntText &num)
{
    const char *p = text.c_str();
    num.negative = *p == '-';
    if (*p == '-' || *p == '+') p++;
    return parse_magnitude(p, num.mag, &num.end, num.overflow);
}

} // namespace

// Strip whitespace on both ends.
std::string ini_trim(const std::string &text)
{
    size_t b = 0, e = text.size();
    while (b < e && is_blank(text[b])) b++;
    while (e > b && is_blank(text[e - 1])) e--;
    return text.substr(b, e - b);
}

// Strip whitespace at the end.
std::string ini_rtrim(const std::string &text)
{
    size_t e = text.size();
    while (e > 0 && is_blank(text[e - 1])) e--;
    return text.substr(0, e);
}

// [A-Za-z0-9_]+ not starting with a digit.
bool ini_valid_identifier(const std::string &name)
{
    if (name.empty() || isdigit((unsigned char)name[0])) return false;
    for (char c : name)
        if (!isalnum((unsigned char)c) && c != '_') return false;
    return true;
}

// Signed integer conversion with range check.
IniConv ini_parse_int(const std::string &text, long long &value)
{
    IntText num;
    if (!parse_integer(text, num)) return IniConv::invalid;
    unsigned long long limit = num.negative ? (unsigned long long)LLONG_MAX + 1 : LLONG_MAX;
    if (num.overflow || num.mag > limit) return IniConv::range;
    value = num.negative ? (long long)(0ULL - num.mag) : (long long)num.mag;
    return tail_state(num.end);
}

// Unsigned integer conversion; negative values wrap modulo 2^64.
IniConv ini_parse_uint(const std::string &text, unsigned long long &value, bool &wrapped)
{
    IntText num;
    if (!parse_integer(text, num)) return IniConv::invalid;
    if (num.overflow) return IniConv::range;
    wrapped = num.negative && num.mag != 0;
    value = num.negative ? 0ULL - num.mag : num.mag;
    return tail_state(num.end);
}

// Real conversion in the C locale, whatever the program's locale.
IniConv ini_parse_real(const std::string &text, double &value)
{
    static locale_t c_locale = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    const char *p = text.c_str();
    char *end = nullptr;
    errno = 0;
    double v = strtod_l(p, &end, c_locale);
    if (end == p || is_blank(*p)) return IniConv::invalid;
    if (errno == ERANGE && (v > 1.0 || v < -1.0)) return IniConv::range;
    value = v;
    return tail_state(end);
}

// Strict boolean words.
bool ini_parse_bool(const std::string &text, bool &value)
{
    static const char *const truth[] = {"TRUE", "YES", "ON", "1"};
    static const char *const falsity[] = {"FALSE", "NO", "OFF", "0"};
    for (int i = 0; i < 4; i++) {
        if (ini_iequal(text, truth[i]) || ini_iequal(text, falsity[i])) {
            value = ini_iequal(text, truth[i]);
            return true;
        }
    }
    return false;
}

// Case-insensitive ASCII equality.
bool ini_iequal(const std::string &a, const char *b)
{
    return strlen(b) == a.size() && strncasecmp(a.c_str(), b, a.size()) == 0;
}
