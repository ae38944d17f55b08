// tooltable.cc: reads a LinuxCNC tool table file (LinuxCNC's tool table format).
#include "tooltable.hh"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <string>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

// store one "<letter><value>" word into t; false when the letter is unknown or the value bad
bool tool_word(CanonTool &t, char letter, const char *text)
{
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(v)) return false;
    double *axes[] = {&t.offset.x, &t.offset.y, &t.offset.z, &t.offset.a, &t.offset.b,
                      &t.offset.c, &t.offset.u, &t.offset.v, &t.offset.w};
    const char *axis_letters = "XYZABCUVW";
    const char *p = strchr(axis_letters, letter);
    if (p && letter) { *axes[p - axis_letters] = v; return true; }
    switch (letter) {
    case 'T': t.toolno = (int)v; return true;
    case 'P': t.pocketno = (int)v; return true;
    case 'D': t.diameter = v; return true;
    case 'I': t.frontangle = v; return true;
    case 'J': t.backangle = v; return true;
    case 'Q': t.orientation = (int)v; return true;
    default: return false;
    }
}

// parse one line (comment after ';') into t; false when a word is not a tool table word.
// A line without words leaves t.toolno at -1.
bool tool_line(const char *text, CanonTool &t)
{
    std::string copy = text;
    size_t semi = copy.find(';');
    if (semi != std::string::npos) copy.erase(semi);
    char *save = nullptr;
    for (char *w = strtok_r(&copy[0], " \t", &save); w; w = strtok_r(nullptr, " \t", &save))
        if (!tool_word(t, (char)toupper((unsigned char)w[0]), w + 1)) return false;
    return true;
}

} // namespace

// Load path into tools (index 0 = spindle kept, tools appended in load order); a line with
// a word that is not a tool table word (or a value that is not a finite number) is skipped
// with LinuxCNC's "Unrecognized line skipped" warning.
bool load_tool_table(const std::string &path, std::vector<CanonTool> &tools, std::string &error)
{
    FILE *f = fopen(path.c_str(), "r");
    if (!f) {
        error = "emc/tooldata/tooldata_common.cc, 305: Failed to open tool table file '" + path +
                "': " + strerror(errno);
        return false;
    }
    tools.resize(1);
    char line[1024];
    int lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        line[strcspn(line, "\r\n")] = 0;
        CanonTool t;
        if (!tool_line(line, t)) {
            fprintf(stderr, "%s:%d: Unrecognized line skipped: %s\n", path.c_str(), lineno, line);
            continue;
        }
        if (t.toolno >= 0) tools.push_back(t);
    }
    fclose(f);
    return true;
}
