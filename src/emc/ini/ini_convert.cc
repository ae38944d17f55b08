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

// Split an integer's text into the digits to convert and their base: an optional sign is kept,
// a 0x/0o/0b prefix after it (followed by at least one character) is removed.
int strip_radix_prefix(std::string &digits)
{
    size_t sign = digits.size() > 1 && (digits[0] == '-' || digits[0] == '+') ? 1 : 0;
    if (digits.size() <= sign + 2 || digits[sign] != '0') return 10;
    static const struct { char letter; int base; } prefixes[] = {{'x', 16}, {'o', 8}, {'b', 2}};
    for (const auto &prefix : prefixes) {
        if ((digits[sign + 1] | 0x20) == prefix.letter) {
            digits.erase(sign, 2);
            return prefix.base;
        }
    }
    return 10;
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

// Only [A-Za-z0-9_] characters (ASCII; the caller checks for a leading digit).
bool ini_identifier_chars(const std::string &name)
{
    for (char c : name) {
        bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
        if (!ok) return false;
    }
    return true;
}

// Signed integer conversion; out-of-range values are invalid.
IniConv ini_parse_int(const std::string &text, long long &value)
{
    std::string digits = text;
    int base = strip_radix_prefix(digits);
    char *end = nullptr;
    errno = 0;
    long long v = strtoll(digits.c_str(), &end, base);
    if (end == digits.c_str() || errno != 0) return IniConv::invalid;
    value = v;
    return tail_state(end);
}

// Unsigned integer conversion; negative values wrap modulo 2^64 as strtoull does.
IniConv ini_parse_uint(const std::string &text, unsigned long long &value)
{
    std::string digits = text;
    int base = strip_radix_prefix(digits);
    char *end = nullptr;
    errno = 0;
    unsigned long long v = strtoull(digits.c_str(), &end, base);
    if (end == digits.c_str() || errno != 0) return IniConv::invalid;
    value = v;
    return tail_state(end);
}

// Real conversion in the C locale, whatever the program's locale; overflow and underflow are invalid.
IniConv ini_parse_real(const std::string &text, double &value)
{
    static locale_t c_locale = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    const char *p = text.c_str();
    char *end = nullptr;
    errno = 0;
    double v = strtod_l(p, &end, c_locale);
    if (end == p || errno != 0) return IniConv::invalid;
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
