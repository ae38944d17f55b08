// tool_table.cc: parsing and writing LinuxCNC's tool table format; a save never drops a row.
#include "tool_table.hh"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace {

const char OFFSET_LETTERS[] = "XYZABCUVW";

double *offset_field(tooldata_entry_t &e, int i)
{
    double *f[9] = {&e.offset.tran.x, &e.offset.tran.y, &e.offset.tran.z, &e.offset.a,
                    &e.offset.b, &e.offset.c, &e.offset.u, &e.offset.v, &e.offset.w};
    return f[i];
}

// The comment after ';', trimmed.
std::string comment_of(const std::string &line, std::string &data)
{
    size_t semi = line.find(';');
    data = line.substr(0, semi);
    if (semi == std::string::npos) return "";
    std::string c = line.substr(semi + 1);
    size_t a = c.find_first_not_of(" \t"), b = c.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : c.substr(a, b - a + 1);
}

}  // namespace

void ToolTable::clear()
{
    rows_.assign(1, tooldata_empty_entry());
    if (!random_) rows_[0].toolno = -1;
}

// One "T.. P.. X.. ... ;comment" line into e.
bool ToolTable::parse_line(const std::string &line, tooldata_entry_t &e, std::string *why) const
{
    std::string data;
    std::string comment = comment_of(line, data);
    e = tooldata_empty_entry();
    snprintf(e.comment, sizeof e.comment, "%s", comment.c_str());
    std::istringstream words(data);
    std::string w;
    bool have_t = false, have_p = false;
    while (words >> w) {
        char letter = (char)toupper((unsigned char)w[0]);
        const char *num = w.c_str() + 1;
        char *end = nullptr;
        double v = strtod(num, &end);
        if (!*num || !end || *end) { *why = "bad word '" + w + "'"; return false; }
        const char *axis = strchr(OFFSET_LETTERS, letter);
        if (letter == 'T') { e.toolno = (int)v; have_t = true; }
        else if (letter == 'P') { e.pocketno = (int)v; have_p = true; }
        else if (letter == 'D') e.diameter = v;
        else if (letter == 'I') e.frontangle = v;
        else if (letter == 'J') e.backangle = v;
        else if (letter == 'Q') e.orientation = (int)v;
        else if (letter && axis) *offset_field(e, (int)(axis - OFFSET_LETTERS)) = v;
        else { *why = "unknown word '" + w + "'"; return false; }
    }
    if (!have_t) { *why = "no T word"; return false; }
    if (!have_p) { *why = "no P word"; return false; }
    if (e.toolno < 0) { *why = "negative tool number"; return false; }
    if (e.pocketno < 0 || e.pocketno >= TOOLDATA_MAX_ENTRIES) {
        *why = "pocket " + std::to_string(e.pocketno) + " out of range 0.." + std::to_string(TOOLDATA_MAX_ENTRIES - 1);
        return false;
    }
    return true;
}

bool ToolTable::load(const std::string &path, std::vector<std::string> *errors)
{
    std::ifstream in(path);
    if (!in) {
        errors->push_back(path + ": can't open tool table: " + strerror(errno));
        return false;
    }
    clear();
    std::string line;
    int lineno = 0;
    bool ok = true;
    while (std::getline(in, line)) {
        lineno++;
        size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == ';') continue;
        tooldata_entry_t e;
        std::string why;
        if (!parse_line(line, e, &why)) {
            errors->push_back(path + ":" + std::to_string(lineno) + ": " + why);
            ok = false;
            continue;
        }
        if (find(e.toolno) >= 0 && e.toolno != 0) {
            errors->push_back(path + ":" + std::to_string(lineno) + ": tool " + std::to_string(e.toolno) + " listed twice");
            ok = false;
            continue;
        }
        if (random_) put(e.pocketno, e);
        else append(e);
    }
    return ok;
}

// One saved line: T P D offsets I J Q ;comment (values that are 0 are left out).
static std::string format_row(const tooldata_entry_t &e)
{
    char buf[512];
    std::string s;
    snprintf(buf, sizeof buf, "T%d P%d", e.toolno, e.pocketno);
    s = buf;
    if (e.diameter != 0) { snprintf(buf, sizeof buf, " D%f", e.diameter); s += buf; }
    tooldata_entry_t copy = e;
    for (int i = 0; i < 9; i++) {
        double v = *offset_field(copy, i);
        if (v != 0) { snprintf(buf, sizeof buf, " %c%+f", OFFSET_LETTERS[i], v); s += buf; }
    }
    if (e.frontangle != 0) { snprintf(buf, sizeof buf, " I%+f", e.frontangle); s += buf; }
    if (e.backangle != 0) { snprintf(buf, sizeof buf, " J%+f", e.backangle); s += buf; }
    if (e.orientation != 0) { snprintf(buf, sizeof buf, " Q%d", e.orientation); s += buf; }
    s += " ;";
    s += e.comment;
    return s;
}

bool ToolTable::save(const std::string &path, std::string *error) const
{
    std::string tmp = path + ".tmp." + std::to_string(getpid());
    FILE *f = fopen(tmp.c_str(), "w");
    if (!f) {
        *error = tmp + ": can't write tool table: " + strerror(errno);
        return false;
    }
    for (int i = random_ ? 0 : 1; i < (int)rows_.size(); i++) {
        const tooldata_entry_t &e = rows_[i];
        if (e.toolno < 0 || (i == 0 && e.toolno == 0)) continue;
        fprintf(f, "%s\n", format_row(e).c_str());
    }
    bool ok = fflush(f) == 0 && fsync(fileno(f)) == 0;
    ok = fclose(f) == 0 && ok;
    if (!ok || rename(tmp.c_str(), path.c_str()) != 0) {
        *error = path + ": can't save tool table: " + strerror(errno);
        unlink(tmp.c_str());
        return false;
    }
    return true;
}

int ToolTable::find(int toolno) const
{
    if (toolno < 0 || (toolno == 0 && !random_)) return -1;
    for (int i = random_ ? 0 : 1; i < (int)rows_.size(); i++)
        if (rows_[i].toolno == toolno) return i;
    return -1;
}

void ToolTable::put(int index, const tooldata_entry_t &entry)
{
    if (index < 0 || index >= TOOLDATA_MAX_ENTRIES) return;
    while ((int)rows_.size() <= index) {
        tooldata_entry_t e = tooldata_empty_entry();
        if (random_) { e.pocketno = (int)rows_.size(); e.toolno = -1; }
        rows_.push_back(e);
    }
    rows_[index] = entry;
}

int ToolTable::append(const tooldata_entry_t &entry)
{
    if ((int)rows_.size() >= TOOLDATA_MAX_ENTRIES) return -1;
    rows_.push_back(entry);
    return (int)rows_.size() - 1;
}

std::vector<CanonTool> ToolTable::canon_tools() const
{
    std::vector<CanonTool> out(rows_.size());
    for (size_t i = 0; i < rows_.size(); i++) {
        const tooldata_entry_t &e = rows_[i];
        CanonTool &t = out[i];
        t.toolno = e.toolno;
        t.pocketno = e.pocketno;
        t.offset.x = e.offset.tran.x; t.offset.y = e.offset.tran.y; t.offset.z = e.offset.tran.z;
        t.offset.a = e.offset.a; t.offset.b = e.offset.b; t.offset.c = e.offset.c;
        t.offset.u = e.offset.u; t.offset.v = e.offset.v; t.offset.w = e.offset.w;
        t.diameter = e.diameter;
        t.frontangle = e.frontangle;
        t.backangle = e.backangle;
        t.orientation = e.orientation;
    }
    return out;
}
