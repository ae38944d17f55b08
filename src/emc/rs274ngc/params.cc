// params.cc: numbered and named parameters: reading, scoping and write protection (LinuxCNC's parameter rules).
#include <cmath>

#include "interp.hh"

// Read "#..." at pos: #<name>, #n, ##n or #[expr].
double Interp::read_parameter(const std::string &t, size_t &pos)
{
    INTERP_FRAME();
    pos++;
    if (pos < t.size() && t[pos] == '<') {
        std::string name = read_name(t, pos);
        return get_named(name);
    }
    double idx = read_real_value(t, pos);
    double r = std::nearbyint(idx);
    if (std::fabs(idx - r) > 0.0001) throw InterpError("Non integer value for integer");
    if (r < 1 || r >= PARAM_COUNT) throw InterpError("Parameter number out of range");
    return get_numbered((int)r);
}

// Read "<name>" at pos (pos on '<'); returns the name (spaces already removed, lower case).
std::string Interp::read_name(const std::string &t, size_t &pos)
{
    INTERP_FRAME();
    size_t end = t.find('>', pos);
    if (end == std::string::npos) throw InterpError("Named parameter missing closing '>'");
    std::string name = t.substr(pos + 1, end - pos - 1);
    if (name.empty()) throw InterpError("Named parameter format error");
    pos = end + 1;
    return name;
}

// Value of numbered parameter n; position and tool parameters are computed on demand.
double Interp::get_numbered(int n) const
{
    INTERP_FRAME();
    if (n >= 5420 && n <= 5428) return s_.current[n - 5420];
    if (n >= 5021 && n <= 5029) return program_to_machine_pose(s_.current)[n - 5021];
    if (n == 5400) return s_.loaded_tool_number();
    if (n >= 5401 && n <= 5413 && !s_.tools.empty()) {
        const CanonTool &t = s_.tools[0];
        const double off[9] = {t.offset.x, t.offset.y, t.offset.z, t.offset.a, t.offset.b,
                               t.offset.c, t.offset.u, t.offset.v, t.offset.w};
        if (n <= 5409) return off[n - 5401];
        if (n == 5410) return t.diameter;
        if (n == 5411) return t.frontangle;
        if (n == 5412) return t.backangle;
        return t.orientation;
    }
    return s_.params[n];
}

// The loaded tool; an empty spindle is T0 on a non-random changer and -1 on a random one
// (where T0 may be a real tool).
int InterpState::loaded_tool_number() const
{
    int t = tools.empty() ? -1 : tools[0].toolno;
    if (settings.random_toolchanger) return t < 0 ? -1 : t;
    return t < 0 ? 0 : t;
}

// Pocket number of the loaded tool (a random changer's spindle is pocket 0), -1 for none.
int InterpState::loaded_pocket_number() const
{
    if (settings.random_toolchanger) return loaded_tool_number() < 0 ? -1 : 0;
    int i = current_pocket;
    return i > 0 && i < (int)tools.size() ? tools[i].pocketno : -1;
}

// Pocket number of the prepared tool (index 0 is the spindle), -1 when none is prepared.
int InterpState::selected_pocket_number() const
{
    int i = selected_pocket;
    if (i < 0 || i >= (int)tools.size()) return -1;
    return i == 0 ? 0 : tools[i].pocketno;
}

// Refuse writes to read-only numbered parameters.
void Interp::check_numbered_writable(int n) const
{
    INTERP_FRAME();
    if (n < 1 || n >= PARAM_COUNT) throw InterpError("Parameter number out of range");
    if ((n >= 5021 && n <= 5029) || (n >= 5400 && n <= 5413) || (n >= 5420 && n <= 5428))
        throw InterpError("Parameter is readonly");
}

// Refuse writes to predefined named parameters.
void Interp::check_named_writable(const std::string &name) const
{
    INTERP_FRAME();
    double v;
    if (py_named_.count(name))
        throw InterpError("Cannot assign to read-only parameter #<" + name + ">");
    if (name[0] == '_' && const_cast<Interp *>(this)->predefined(name, v))
        throw InterpError("Cannot assign to read-only parameter #<" + name + ">");
    if (name.compare(0, 5, "_ini[") == 0 || name.compare(0, 5, "_hal[") == 0)
        throw InterpError("Cannot assign to read-only parameter #<" + name + ">");
}

// True when a named parameter is defined at this point.
bool Interp::named_exists(const std::string &name)
{
    INTERP_FRAME();
    double v;
    if (name[0] == '_') {
        if (globals_.count(name)) return true;
        return predefined(name, v);
    }
    return calls_.back().locals.count(name) != 0;
}

// Value of a named parameter; undefined -> error.
double Interp::get_named(const std::string &name)
{
    INTERP_FRAME();
    double v = 0;
    if (name[0] == '_') {
        auto it = globals_.find(name);
        if (it != globals_.end()) return it->second;
        if (predefined(name, v)) return v;
    } else {
        auto &loc = calls_.back().locals;
        auto it = loc.find(name);
        if (it != loc.end()) return it->second;
    }
    throw InterpError("Named parameter #<" + name + "> not defined");
}

// Assign a named parameter in its scope (global when it starts with '_').
void Interp::set_named(const std::string &name, double v)
{
    INTERP_FRAME();
    if (name[0] == '_')
        globals_[name] = v;
    else
        calls_.back().locals[name] = v;
}
