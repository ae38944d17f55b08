// ini_escape.cc: decoding of backslash escapes in INI values (C-like, octal, \x, \u, \U) and UTF-8 checks.
#include "ini_text.hh"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace {

// Value of a hex digit, or -1.
int hex_value(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Value of `count` hex digits at raw[pos] (the caller checked they exist); -1 when one is not hex.
long read_hex(const std::string &raw, size_t pos, size_t count)
{
    long value = 0;
    for (size_t i = 0; i < count; i++) {
        if (hex_value(raw[pos + i]) < 0) return -1;
        value = value * 16 + hex_value(raw[pos + i]);
    }
    return value;
}

// Append the UTF-8 encoding of a code point (at most U+10FFFF).
void append_utf8(std::string &out, uint32_t cp)
{
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xC0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += char(0xE0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    } else {
        out += char(0xF0 | (cp >> 18));
        out += char(0x80 | ((cp >> 12) & 0x3F));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    }
}

// Control characters written as single-letter escapes, in the same order as their letters.
const char simple_bytes[] = "\a\b\f\n\r\t\v\\";
const char simple_letters[] = "abfnrtv\\";

// An escape being decoded: the value, the position of the letter after '\', and the result.
struct Escape {
    const std::string &raw;
    size_t pos;        // index of the letter after the backslash
    std::string &out;  // decoded text so far
    std::string &error;
    size_t used = 0;   // characters consumed after the backslash
    // Characters left after the backslash.
    size_t left() const { return raw.size() - pos; }
};

// Store an error and report failure.
bool fail(Escape &e, const std::string &what)
{
    e.error = what;
    return false;
}

// Code point as "uD800" / "U00110000" in error texts.
std::string code_text(char letter, unsigned long cp, int digits)
{
    char buf[24];
    snprintf(buf, sizeof buf, "%c%0*lX", letter, digits, cp);
    return buf;
}

// \[0-3][0-7]{0,2}: an octal byte.
bool decode_octal(Escape &e)
{
    long value = 0;
    while (e.used < 3 && e.used < e.left() && e.raw[e.pos + e.used] >= '0' &&
           e.raw[e.pos + e.used] <= '7')
        value = value * 8 + (e.raw[e.pos + e.used++] - '0');
    if (value == 0) return fail(e, "Embedded octal NUL character not supported");
    e.out += char(value);
    return true;
}

// \xHH: a hex byte.
bool decode_hex_byte(Escape &e)
{
    if (e.left() < 3) return fail(e, "Improper hex escape");
    long value = read_hex(e.raw, e.pos + 1, 2);
    if (value < 0) return fail(e, "Invalid hex '" + e.raw.substr(e.pos + 1, 2) + "' in hex escape");
    if (value == 0) return fail(e, "Embedded hex NUL character not supported");
    e.out += char(value);
    e.used = 3;
    return true;
}

// The low half of a UTF-16 surrogate pair after a high one; 0 on error.
long decode_low_surrogate(Escape &e)
{
    if (e.left() < 11 || e.raw.compare(e.pos + 5, 2, "\\u") != 0) {
        fail(e, "Missing low surrogate in UTF-16");
        return 0;
    }
    long low = read_hex(e.raw, e.pos + 7, 4);
    if (low < 0) {
        fail(e, "Invalid hex '" + e.raw.substr(e.pos + 7, 4) + "' in UTF-16 low surrogate escape");
        return 0;
    }
    if (low < 0xDC00 || low > 0xDFFF) {
        fail(e, "Invalid low surrogate value " + code_text('u', low, 4) + " in UTF-16");
        return 0;
    }
    return low;
}

// \uHHHH, with a following \uHHHH when the first is a high surrogate.
bool decode_utf16(Escape &e)
{
    if (e.left() < 5) return fail(e, "Improper UTF-16 escape");
    long cp = read_hex(e.raw, e.pos + 1, 4);
    if (cp < 0)
        return fail(e, "Invalid hex value '" + e.raw.substr(e.pos + 1, 4) + "' in UTF-16 escape");
    if (cp == 0) return fail(e, "Embedded UTF-16 NUL character not supported");
    e.used = 5;
    if (cp >= 0xDC00 && cp <= 0xDFFF)
        return fail(e, "Invalid high surrogate value " + code_text('u', cp, 4) + " in UTF-16");
    if (cp >= 0xD800 && cp <= 0xDBFF) {
        long low = decode_low_surrogate(e);
        if (low == 0) return false;
        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
        e.used = 11;
    }
    append_utf8(e.out, uint32_t(cp));
    return true;
}

// \UHHHHHHHH: a code point up to U+10FFFF.
bool decode_utf32(Escape &e)
{
    if (e.left() < 9) return fail(e, "Improper UTF-32 escape");
    long cp = read_hex(e.raw, e.pos + 1, 8);
    if (cp < 0)
        return fail(e, "Invalid hex value '" + e.raw.substr(e.pos + 1, 8) + "' in UTF-32 escape");
    if (cp == 0) return fail(e, "Embedded UTF-32 NUL character not supported");
    if (cp > 0x10FFFF) return fail(e, "Invalid code point " + code_text('U', cp, 8) + " in UTF-32 escape");
    append_utf8(e.out, uint32_t(cp));
    e.used = 9;
    return true;
}

// Decode the escape whose letter is at raw[pos]; false with e.error on a malformed one.
bool decode_escape(Escape &e, std::vector<std::string> &warnings)
{
    char c = e.raw[e.pos];
    const char *simple = c ? strchr(simple_letters, c) : nullptr;
    if (simple) {
        e.out += simple_bytes[simple - simple_letters];
        e.used = 1;
        return true;
    }
    if (c >= '0' && c <= '3') return decode_octal(e);
    if (c == 'x') return decode_hex_byte(e);
    if (c == 'u') return decode_utf16(e);
    if (c == 'U') return decode_utf32(e);
    warnings.push_back(std::string("Improper escape of '") + c + "', ignored");
    e.out += '\\';
    e.out += c;
    e.used = 1;
    return true;
}

} // namespace

// Decode every escape of a value (see ini_text.hh).
bool ini_decode_escapes(const std::string &raw, std::string &out,
                        std::vector<std::string> &warnings, std::string &error)
{
    out.clear();
    for (size_t i = 0; i < raw.size(); i++) {
        if (raw[i] != '\\' || i + 1 == raw.size()) {
            out += raw[i];
            continue;
        }
        Escape e{raw, i + 1, out, error};
        if (!decode_escape(e, warnings)) return false;
        i += e.used;
    }
    if (!ini_valid_utf8(out)) {
        error = "Value contains invalid UTF-8 sequence";
        return false;
    }
    return true;
}

// Escape a value for NAME=<value> output: edge blanks as \x20, controls and backslashes escaped.
std::string ini_escape_value(const std::string &value)
{
    std::string out;
    for (size_t i = 0; i < value.size(); i++) {
        char c = value[i];
        const char *simple = strchr(simple_bytes, c);
        if (c == ' ' && (i == 0 || i + 1 == value.size())) {
            out += "\\x20";
        } else if (c && simple) {
            out += '\\';
            out += simple_letters[simple - simple_bytes];
        } else if ((unsigned char)c < ' ' || c == 0x7F) {
            char buf[8];
            snprintf(buf, sizeof buf, "\\x%02x", (unsigned char)c);
            out += buf;
        } else {
            out += c;
        }
    }
    return out;
}

// Check UTF-8 well-formedness (no overlongs, surrogates or code points past U+10FFFF).
bool ini_valid_utf8(const std::string &text)
{
    const unsigned char *s = reinterpret_cast<const unsigned char *>(text.data());
    size_t n = text.size();
    for (size_t i = 0; i < n;) {
        unsigned c = s[i];
        int len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (len == 0 || i + len > n) return false;
        uint32_t cp = len == 1 ? c : c & (0x7F >> len);
        for (int k = 1; k < len; k++) {
            if ((s[i + k] & 0xC0) != 0x80) return false;
            cp = (cp << 6) | (s[i + k] & 0x3F);
        }
        static const uint32_t min_cp[5] = {0, 0, 0x80, 0x800, 0x10000};
        if (cp < min_cp[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
        i += len;
    }
    return true;
}
