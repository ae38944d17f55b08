// ini_escape.cc: decoding of backslash escapes in INI values (C-like, octal, \x, \u, \U) and UTF-8 checks.
#include "ini_text.hh"

#include <cstdint>

namespace {

// Value of a hex digit, or -1.
int hex_value(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Read exactly `count` hex digits at raw[pos]; -1 when they are not all there.
long read_hex(const std::string &raw, size_t pos, int count)
{
    long value = 0;
    for (int i = 0; i < count; i++) {
        if (pos + i >= raw.size() || hex_value(raw[pos + i]) < 0) return -1;
        value = value * 16 + hex_value(raw[pos + i]);
    }
    return value;
}

// Append the UTF-8 encoding of a code point.
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

// Single-letter escapes: letter -> byte, 0 when not one of them.
char simple_escape(char c)
{
    switch (c) {
    case 'a': return '\a';
    case 'b': return '\b';
    case 'f': return '\f';
    case 'n': return '\n';
    case 'r': return '\r';
    case 't': return '\t';
    case 'v': return '\v';
    case '\\': return '\\';
    default: return 0;
    }
}

// Decode \u / \U at raw[pos] (pos at the letter); returns chars consumed after '\', 0 on error.
size_t decode_unicode(const std::string &raw, size_t pos, std::string &out, std::string &error)
{
    bool wide = raw[pos] == 'U';
    long cp = read_hex(raw, pos + 1, wide ? 8 : 4);
    size_t used = wide ? 9 : 5;
    if (cp < 0) {
        error = std::string("Invalid '\\") + raw[pos] + "' escape: expected " + (wide ? "8" : "4") +
                " hex digits";
        return 0;
    }
    if (!wide && cp >= 0xD800 && cp <= 0xDBFF) {
        long low = -1;
        if (raw.compare(pos + 5, 2, "\\u") == 0) low = read_hex(raw, pos + 7, 4);
        if (low < 0xDC00 || low > 0xDFFF) {
            error = "Invalid '\\u' escape: high surrogate without a low surrogate";
            return 0;
        }
        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
        used = 11;
    }
    if (cp == 0 || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
        error = cp == 0 ? "Escape yields a NUL character, which is not allowed"
                        : "Escape yields an invalid unicode code point";
        return 0;
    }
    append_utf8(out, uint32_t(cp));
    return used;
}

// Decode a numeric byte escape (octal or \x) at raw[pos]; chars consumed after '\', 0 on error.
size_t decode_byte(const std::string &raw, size_t pos, std::string &out, std::string &error)
{
    long value = 0;
    size_t used = 0;
    if (raw[pos] == 'x') {
        value = read_hex(raw, pos + 1, 2);
        used = 3;
        if (value < 0) {
            error = "Invalid '\\x' escape: expected 2 hex digits";
            return 0;
        }
    } else {
        while (used < 3 && pos + used < raw.size() && raw[pos + used] >= '0' &&
               raw[pos + used] <= '7')
            value = value * 8 + (raw[pos + used++] - '0');
    }
    if (value == 0) {
        error = "Escape yields a NUL character, which is not allowed";
        return 0;
    }
    out += char(value);
    return used;
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
        char c = raw[i + 1];
        size_t used = 1;
        if (simple_escape(c)) {
            out += simple_escape(c);
        } else if (c == 'u' || c == 'U') {
            used = decode_unicode(raw, i + 1, out, error);
        } else if (c == 'x' || (c >= '0' && c <= '3')) {
            used = decode_byte(raw, i + 1, out, error);
        } else {
            warnings.push_back(std::string("Improper escape of '") + c + "', ignored");
            out += '\\';
            out += c;
        }
        if (used == 0) return false;
        i += used;
    }
    if (!ini_valid_utf8(out)) {
        error = "Value is not valid UTF-8";
        return false;
    }
    return true;
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
