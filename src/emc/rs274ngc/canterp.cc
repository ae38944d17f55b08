// canterp.cc: the "canterp" interpreter plugin (rs274 -p canterp.so): replays printed canon calls.
// Input lines look like rs274 output ("  1 N..... STRAIGHT_FEED(1.0, 2.0, ...)"): the call name and
// its comma-separated arguments are read and the same call is made on the canon.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "interp_base.hh"

namespace {

// Arguments of one call as text.
using Args = std::vector<std::string>;

// numeric argument i (missing -> 0)
double num(const Args &a, size_t i)
{
    return i < a.size() ? strtod(a[i].c_str(), nullptr) : 0.0;
}

// pose from arguments first..first+8
CanonPose pose(const Args &a, size_t first)
{
    return CanonPose{num(a, first), num(a, first + 1), num(a, first + 2),
                     num(a, first + 3), num(a, first + 4), num(a, first + 5),
                     num(a, first + 6), num(a, first + 7), num(a, first + 8)};
}

// text argument without quotes
std::string text(const Args &a)
{
    std::string t = a.empty() ? "" : a[0];
    if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = t.substr(1, t.size() - 2);
    return t;
}

// The replay interpreter.
class CanonReplay : public InterpBase {
public:
    explicit CanonReplay(Canon &out) : out_(out) { build_table(); }

    bool load_ini(const std::string &) override { return true; }
    void set_var_file(const std::string &) override {}
    void set_tools(const std::vector<CanonTool> &) override {}
    void set_task(bool) override {}
    void set_block_delete(bool) override {}
    void init() override {}
    // read the whole input file
    void open(const std::string &path) override
    {
        std::ifstream in(path);
        if (!in) throw std::runtime_error("Unable to open file <" + path + ">");
        lines_.clear();
        std::string l;
        while (std::getline(in, l)) lines_.push_back(l);
        next_ = 0;
    }
    // replay the next line
    InterpStatus execute_next() override
    {
        if (next_ >= lines_.size()) return fail("File ended with no PROGRAM_END", "", true);
        return execute_line(lines_[next_++]);
    }
    InterpStatus execute_line(const std::string &line) override;
    void close() override {}
    void exit() override {}
    const std::string &error_text() const override { return error_; }
    const std::string &error_line() const override { return error_line_; }
    bool at_end_of_file() const override { return eof_; }
    const std::string &line_text() const override { return empty_; }

private:
    // record an error
    InterpStatus fail(const std::string &what, const std::string &line, bool eof)
    {
        error_ = what;
        error_line_ = line;
        eof_ = eof;
        return INTERP_ERROR;
    }
    void build_table();

    Canon &out_;
    std::vector<std::string> lines_;
    size_t next_ = 0;
    std::string error_, error_line_, empty_;
    bool eof_ = false;
    std::map<std::string, std::function<void(const Args &)>> calls_;
};

// Fill the call-name table.
void CanonReplay::build_table()
{
    Canon &c = out_;
    calls_["USE_LENGTH_UNITS"] = [&c](const Args &a) {
        c.use_length_units(text(a) == "CANON_UNITS_INCHES" ? CANON_UNITS_INCHES : CANON_UNITS_MM);
    };
    calls_["STRAIGHT_TRAVERSE"] = [&c](const Args &a) { c.straight_traverse(-1, pose(a, 0)); };
    calls_["STRAIGHT_FEED"] = [&c](const Args &a) { c.straight_feed(-1, pose(a, 0)); };
    calls_["ARC_FEED"] = [&c](const Args &a) {
        c.arc_feed(-1, num(a, 0), num(a, 1), num(a, 2), num(a, 3), atoi(a.size() > 4 ? a[4].c_str() : "0"),
                   num(a, 5), num(a, 6), num(a, 7), num(a, 8), num(a, 9), num(a, 10), num(a, 11));
    };
    calls_["SET_FEED_RATE"] = [&c](const Args &a) { c.set_feed_rate(num(a, 0)); };
    calls_["DWELL"] = [&c](const Args &a) { c.dwell(num(a, 0)); };
    calls_["SET_SPINDLE_SPEED"] = [&c](const Args &a) { c.set_spindle_speed((int)num(a, 0), num(a, 1)); };
    calls_["START_SPINDLE_CLOCKWISE"] = [&c](const Args &a) { c.start_spindle_clockwise((int)num(a, 0)); };
    calls_["START_SPINDLE_COUNTERCLOCKWISE"] = [&c](const Args &a) {
        c.start_spindle_counterclockwise((int)num(a, 0));
    };
    calls_["STOP_SPINDLE_TURNING"] = [&c](const Args &a) { c.stop_spindle_turning((int)num(a, 0)); };
    calls_["MIST_ON"] = [&c](const Args &) { c.mist_on(); };
    calls_["MIST_OFF"] = [&c](const Args &) { c.mist_off(); };
    calls_["FLOOD_ON"] = [&c](const Args &) { c.flood_on(); };
    calls_["FLOOD_OFF"] = [&c](const Args &) { c.flood_off(); };
    calls_["SELECT_TOOL"] = [&c](const Args &a) { c.select_tool((int)num(a, 0)); };
    calls_["CHANGE_TOOL"] = [&c](const Args &) { c.change_tool(); };
    calls_["COMMENT"] = [&c](const Args &a) { c.comment(text(a)); };
    calls_["MESSAGE"] = [&c](const Args &a) { c.message(text(a)); };
    calls_["PROGRAM_STOP"] = [&c](const Args &) { c.program_stop(); };
    calls_["OPTIONAL_PROGRAM_STOP"] = [&c](const Args &) { c.optional_program_stop(); };
    calls_["PROGRAM_END"] = [&c](const Args &) { c.program_end(); };
}

// Split "NAME(a, b, c)" at the last word before '(' and run the call.
InterpStatus CanonReplay::execute_line(const std::string &line)
{
    size_t open = line.find('(');
    size_t close = line.rfind(')');
    if (open == std::string::npos || close == std::string::npos || close < open)
        return line.find_first_not_of(" \t\r") == std::string::npos
                   ? INTERP_OK : fail("canterp: no canon call on line", line, false);
    size_t start = line.find_last_of(" \t", open);
    std::string name = line.substr(start == std::string::npos ? 0 : start + 1,
                                   open - (start == std::string::npos ? 0 : start + 1));
    auto it = calls_.find(name);
    if (it == calls_.end()) return fail("canterp: unknown canon call " + name, line, false);
    Args args;
    std::string inner = line.substr(open + 1, close - open - 1);
    size_t p = 0;
    while (p <= inner.size() && !inner.empty()) {
        size_t comma = inner.find(',', p);
        if (comma == std::string::npos) comma = inner.size();
        std::string a = inner.substr(p, comma - p);
        a.erase(0, a.find_first_not_of(" \t"));
        args.push_back(a);
        p = comma + 1;
    }
    it->second(args);
    return name == "PROGRAM_END" ? INTERP_EXIT : INTERP_OK;
}

} // namespace

// Plugin entry point.
extern "C" InterpBase *make_interp(Canon &out)
{
    return new CanonReplay(out);
}
