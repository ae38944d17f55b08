// comments.cc: plain and active comments (MSG, DEBUG, PRINT, LOG*, ABORT) and parameter expansion.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "interp.hh"

namespace {

// case-insensitive "keyword," prefix test after leading blanks; sets rest to the text after ','
bool keyword(const std::string &c, const char *kw, std::string &rest)
{
    size_t i = c.find_first_not_of(" \t");
    if (i == std::string::npos) return false;
    size_t n = strlen(kw);
    if (c.size() < i + n + 1 || strncasecmp(c.c_str() + i, kw, n) != 0 || c[i + n] != ',')
        return false;
    rest = c.substr(i + n + 1);
    return true;
}

// format one value with the current format (decimals < 0: "%lf")
std::string format_value(double v, int decimals)
{
    char buf[400];
    if (decimals < 0) decimals = 6;
    snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);
    return s;
}

} // namespace

// Expand #n, #<name> and %d/%f/%.Nf format tokens in active-comment text.
std::string Interp::expand_text(const std::string &text)
{
    INTERP_FRAME();
    std::string outs;
    int decimals = -1;
    for (size_t i = 0; i < text.size(); i++) {
        char c = text[i];
        if (c == '%' && i + 1 < text.size()) {
            char n = text[i + 1];
            if (n == 'd') { decimals = 0; i++; continue; }
            if (n == 'f') { decimals = 4; i++; continue; }
            if (n == '.') {
                if (i + 3 < text.size() + 0 && isdigit((unsigned char)text[i + 2]) && text[i + 3] == 'f') {
                    decimals = text[i + 2] - '0';
                    i += 3;
                }
                continue;
            }
        }
        if (c != '#') { outs += c; continue; }
        outs += expand_param(text, i, decimals);
    }
    return outs;
}

// Expand one parameter reference starting at text[i] == '#'; advances i to its last char.
std::string Interp::expand_param(const std::string &text, size_t &i, int decimals)
{
    INTERP_FRAME();
    if (i + 1 < text.size() && text[i + 1] == '<') {
        size_t end = text.find('>', i);
        if (end == std::string::npos) return "#";
        std::string name;
        for (size_t k = i + 2; k < end; k++)
            if (text[k] != ' ' && text[k] != '\t') name += (char)tolower((unsigned char)text[k]);
        i = end;
        try {
            if (name.empty() || !named_exists(name)) return "######";
            return format_value(get_named(name), decimals);
        } catch (const InterpError &) {   // a namedparams function that failed: shown, not fatal
            return "######";
        }
    }
    size_t k = i + 1;
    while (k < text.size() && isdigit((unsigned char)text[k])) k++;
    if (k == i + 1) return "#";
    long n = atol(text.substr(i + 1, k - i - 1).c_str());
    i = k - 1;
    if (n < 1 || n >= PARAM_COUNT) return "######";
    return format_value(get_numbered((int)n), decimals);
}

// Comment step (3): COMMENT or the active comment's action.
void Interp::do_comment(Block &b)
{
    INTERP_FRAME();
    const std::string &c = b.comment;
    std::string rest;
    if (python_comment(c)) return;
    if (keyword(c, "msg", rest)) { out().message(rest); return; }
    if (keyword(c, "debug", rest)) {
        if (s_.params[5599] > 0) out().message(expand_text(rest));
        return;
    }
    if (keyword(c, "print", rest)) {
        std::string t = expand_text(rest);
        fprintf(stdout, "%s\n", t.c_str());
        return;
    }
    if (keyword(c, "log", rest)) { out().log(expand_text(rest)); return; }
    if (keyword(c, "logopen", rest)) { out().logopen(rest); return; }
    if (keyword(c, "logappend", rest)) { out().logappend(rest); return; }
    if (keyword(c, "abort", rest)) throw InterpError(expand_text(rest));
    size_t i = c.find_first_not_of(" \t");
    std::string text = i == std::string::npos ? "" : c.substr(i);
    if (strcasecmp(text.c_str(), "logclose") == 0) { out().logclose(); return; }
    out().comment(text);
}
