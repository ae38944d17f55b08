// ini_text.hh: text helpers of the INI library: trimming, escape decoding and number conversion.
#ifndef OPENEMC_INI_TEXT_HH
#define OPENEMC_INI_TEXT_HH

#include <string>
#include <vector>

// Outcome of a number conversion: usable, usable with trailing text, or no number / out of range.
enum class IniConv { ok, trailing, invalid };

// Strip leading and trailing whitespace (space, tab, CR, LF, VT, FF).
std::string ini_trim(const std::string &text);
// Strip trailing whitespace only.
std::string ini_rtrim(const std::string &text);
// True when every character of name is one of [A-Za-z0-9_].
bool ini_identifier_chars(const std::string &name);
// Decode the escapes of a value; false (with `error`) on a malformed or NUL-producing escape or
// invalid UTF-8. Unknown escapes are kept and reported in `warnings`.
bool ini_decode_escapes(const std::string &raw, std::string &out,
                        std::vector<std::string> &warnings, std::string &error);
// True when text is well-formed UTF-8.
bool ini_valid_utf8(const std::string &text);
// Signed integer: optional sign, decimal or 0x/0o/0b prefix.
IniConv ini_parse_int(const std::string &text, long long &value);
// Unsigned integer (same syntax); a negative value is converted modulo 2^64.
IniConv ini_parse_uint(const std::string &text, unsigned long long &value);
// Escape a value so that parsing NAME=<result> gives it back (edge blanks, controls, backslashes).
std::string ini_escape_value(const std::string &value);
// Real number (strtod in the C locale).
IniConv ini_parse_real(const std::string &text, double &value);
// Strict boolean (TRUE YES ON 1 FALSE NO OFF 0, any case); false when not one of them.
bool ini_parse_bool(const std::string &text, bool &value);
// Case-insensitive ASCII comparison.
bool ini_iequal(const std::string &a, const char *b);

#endif
