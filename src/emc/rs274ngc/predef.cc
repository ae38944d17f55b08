// predef.cc: predefined read-only named parameters (#<_x>, #<_metric>, #<_ini[sec]key>, ...).
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "inifile.hh"
#include "interp.hh"

namespace {

// a table entry: name and a function computing the value from the interpreter state
struct Predef {
    const char *name;
    double (*fn)(const InterpState &s);
};

// 1.0 when flag is true
double b(bool flag) { return flag ? 1.0 : 0.0; }

const Predef PREDEFS[] = {
    {"_vmajor", [](const InterpState &) { return 2.1; }},
    {"_vminor", [](const InterpState &) { return 0.0; }},
    {"_line", [](const InterpState &s) { return (double)s.sequence_number; }},
    {"_motion_mode", [](const InterpState &s) { return (double)s.motion_mode; }},
    {"_plane", [](const InterpState &s) {
         static const double codes[] = {0, 170, 190, 180, 171, 191, 181};
         return codes[s.plane]; }},
    {"_ccomp", [](const InterpState &s) {
         return (double)(s.comp_code == 411 ? 410 : s.comp_code == 421 ? 420 : s.comp_code); }},
    {"_metric", [](const InterpState &s) { return b(s.units == CANON_UNITS_MM); }},
    {"_imperial", [](const InterpState &s) { return b(s.units == CANON_UNITS_INCHES); }},
    {"_absolute", [](const InterpState &s) { return b(!s.distance_incremental); }},
    {"_incremental", [](const InterpState &s) { return b(s.distance_incremental); }},
    {"_inverse_time", [](const InterpState &s) { return b(s.feed_mode == FEED_INVERSE_TIME); }},
    {"_units_per_minute",
     [](const InterpState &s) { return b(s.feed_mode == FEED_UNITS_PER_MINUTE); }},
    {"_units_per_rev", [](const InterpState &s) { return b(s.feed_mode == FEED_UNITS_PER_REV); }},
    {"_coord_system", [](const InterpState &s) {
         static const double codes[] = {0, 540, 550, 560, 570, 580, 590, 591, 592, 593};
         return codes[s.origin_index]; }},
    {"_tool_offset", [](const InterpState &s) {
         for (double v : s.tool_offset)
             if (v != 0.0) return 1.0;
         return 0.0; }},
    {"_retract_old_z", [](const InterpState &s) { return b(s.retract == RETRACT_OLD_Z); }},
    {"_retract_r_plane", [](const InterpState &s) { return b(s.retract == RETRACT_R_PLANE); }},
    {"_spindle_rpm_mode", [](const InterpState &s) { return b(!s.css_mode[0]); }},
    {"_spindle_css_mode", [](const InterpState &s) { return b(s.css_mode[0]); }},
    {"_ijk_absolute_mode", [](const InterpState &s) { return b(s.ijk_absolute); }},
    {"_lathe_diameter_mode", [](const InterpState &s) { return b(s.lathe_diameter); }},
    {"_lathe_radius_mode", [](const InterpState &s) { return b(!s.lathe_diameter); }},
    {"_spindle_on", [](const InterpState &s) { return b(s.spindle_dir[0] != CANON_STOPPED); }},
    {"_spindle_cw", [](const InterpState &s) { return b(s.spindle_dir[0] == CANON_CLOCKWISE); }},
    {"_mist", [](const InterpState &s) { return b(s.mist); }},
    {"_flood", [](const InterpState &s) { return b(s.flood); }},
    {"_speed_override", [](const InterpState &s) { return b(s.speed_override); }},
    {"_feed_override", [](const InterpState &s) { return b(s.feed_override); }},
    {"_adaptive_feed", [](const InterpState &s) { return b(s.adaptive_feed); }},
    {"_feed_hold", [](const InterpState &s) { return b(s.feed_hold); }},
    {"_feed", [](const InterpState &s) { return s.feed_rate; }},
    {"_rpm", [](const InterpState &s) { return std::fabs(s.speed[0]); }},
    {"_current_tool", [](const InterpState &s) { return (double)s.loaded_tool_number(); }},
    {"_current_pocket", [](const InterpState &s) { return (double)s.loaded_pocket_number(); }},
    {"_selected_tool", [](const InterpState &s) { return (double)s.selected_tool; }},
    {"_selected_pocket", [](const InterpState &s) { return (double)s.selected_pocket_number(); }},
    {"_call_level", [](const InterpState &s) { return (double)s.call_level; }},
    {"_metric_machine", [](const InterpState &s) { return (double)s.settings.metric_machine; }},
};

// upper-case copy of a string
std::string upper(std::string v)
{
    for (char &c : v) c = (char)toupper((unsigned char)c);
    return v;
}

} // namespace

// Look up a predefined parameter; false when name is not one.
bool Interp::predefined(const std::string &name, double &v)
{
    INTERP_FRAME();
    if (python_named(name, v)) return true;
    for (const Predef &p : PREDEFS) {
        if (name == p.name) {
            v = p.fn(s_);
            return true;
        }
    }
    if (predefined_position(name, v) || interp_value(name, v)) return true;
    if (name.compare(0, 5, "_hal[") == 0) return hal_value(name, v);
    if (name.compare(0, 5, "_ini[") == 0) return ini_value(name, v);
    return false;
}

// #<_x> .. #<_w> (current position) and #<_abs_x> .. #<_abs_w> (machine position).
bool Interp::predefined_position(const std::string &name, double &v) const
{
    static const char axes[] = "xyzabcuvw";
    if (name.size() == 2 && strchr(axes, name[1])) {
        v = s_.current[strchr(axes, name[1]) - axes];
        return true;
    }
    if (name.size() == 6 && name.compare(0, 5, "_abs_") == 0 && strchr(axes, name[5])) {
        v = program_to_machine_pose(s_.current)[strchr(axes, name[5]) - axes];
        return true;
    }
    return false;
}

// Predefined values the interpreter (not the state) holds: _task, _remap_level, _value...
bool Interp::interp_value(const std::string &name, double &v) const
{
    const struct { const char *name; double value; } values[] = {
        {"_task", task_ ? 1.0 : 0.0}, {"_remap_level", (double)remap_stack_.size()},
        {"_value", value_}, {"_value_returned", value_returned_},
    };
    for (const auto &e : values) {
        if (name != e.name) continue;
        v = e.value;
        return true;
    }
    return false;
}

// #<_ini[section]key>: the INI value as a number (cached), when INI_VARS is on.
bool Interp::ini_value(const std::string &name, double &v)
{
    if (!s_.settings.ini_vars || ini_path_.empty()) return false;
    auto it = ini_cache_.find(name);
    if (it != ini_cache_.end()) { v = it->second; return true; }
    size_t close = name.find(']');
    if (close == std::string::npos) return false;
    IniFile ini(ini_path_);
    if (!ini.IsOpen()) return false;
    auto text = ini.Find(upper(name.substr(close + 1)), upper(name.substr(5, close - 5)));
    if (!text) return false;
    char *end = nullptr;
    v = strtod(text->c_str(), &end);
    if (end == text->c_str()) return false;
    ini_cache_[name] = v;
    return true;
}

// #<_hal[name]>: sampled from the HAL reader when HAL_PIN_VARS is on; otherwise not defined.
bool Interp::hal_value(const std::string &name, double &v)
{
    INTERP_FRAME();
    size_t close = name.find(']');
    if (close != name.size() - 1 || !s_.settings.hal_pin_vars || !hal_reader_) return false;
    return hal_reader_(name.substr(5, close - 5), v);
}

// Names of the built-in predefined parameters (for Python's params.globals()).
std::vector<std::string> Interp::predefined_names()
{
    std::vector<std::string> names;
    for (const Predef &p : PREDEFS) names.push_back(p.name);
    for (const char *axis = "xyzabcuvw"; *axis; axis++) {
        names.push_back(std::string("_") + *axis);
        names.push_back(std::string("_abs_") + *axis);
    }
    for (const char *n : {"_task", "_remap_level", "_value", "_value_returned"}) names.push_back(n);
    return names;
}
