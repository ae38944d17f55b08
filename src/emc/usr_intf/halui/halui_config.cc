// halui_config.cc: the INI keys halui reads: joints, axes, spindles, override limits, MDI commands, the GUI bridge's command names.
#include <cctype>
#include <cstdio>

#include "halui.hh"
#include "inifile.hh"

const char HALUI_AXIS_LETTERS[EMCMOT_MAX_AXIS + 1] = "xyzabcuvw";

namespace {

// "file:line: " of a key, or "file: " when it is missing.
std::string where(const IniFile &ini, const char *section, const char *key)
{
    const IniEntry *e = ini.FindEntry(key, section);
    if (!e) return ini.Path() + ": ";
    return e->file + ":" + std::to_string(e->line) + ": ";
}

// An integer key that must lie in [lo, hi]; missing: *out unchanged unless required.
bool read_int(const IniFile &ini, const char *section, const char *key, long lo, long hi,
              bool required, int *out)
{
    if (!ini.Find(key, section)) {
        if (!required) return true;
        fprintf(stderr, "halui: %s[%s]%s is missing\n", where(ini, section, key).c_str(), section, key);
        return false;
    }
    std::optional<long long> v = ini.FindInt(key, section);
    if (!v || *v < lo || *v > hi) {
        fprintf(stderr, "halui: %s[%s]%s must be an integer from %ld to %ld\n",
                where(ini, section, key).c_str(), section, key, lo, hi);
        return false;
    }
    *out = static_cast<int>(*v);
    return true;
}

// A real key (a malformed one is diagnosed by the INI library and the default kept).
void read_real(const IniFile &ini, const char *section, const char *key, double *out)
{
    if (std::optional<double> v = ini.FindReal(key, section)) *out = *v;
}

// [TRAJ]COORDINATES letters as an axis mask (X Y Z when the key is missing).
unsigned axis_mask(const IniFile &ini)
{
    std::optional<std::string> coords = ini.Find("COORDINATES", "TRAJ");
    if (!coords) return 7;
    unsigned mask = 0;
    for (char c : *coords)
        for (int i = 0; i < EMCMOT_MAX_AXIS; i++)
            if (std::tolower(static_cast<unsigned char>(c)) == HALUI_AXIS_LETTERS[i]) mask |= 1u << i;
    return mask;
}

// Turn text into a HAL name part: letters, digits, '_', '-' and '.' kept, others '-'.
std::string hal_name_part(const std::string &text)
{
    std::string out;
    for (char c : text)
        out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.') ? c : '-';
    return out;
}

// The GUI bridge's command pins: MDI_COMMAND_<name> in [MDI_COMMAND_LIST] and
// MACRO_COMMAND_<name> in [MACROS] give <name>; repeated MDI_COMMAND / MACRO keys (also
// the legacy [DISPLAY]MACRO) are named by their index, 00 up.
std::vector<std::string> gui_command_names(const IniFile &ini)
{
    std::vector<std::string> names;
    int index = 0;
    auto scan = [&](const char *section, const std::string &named, const std::string &plain) {
        for (const auto &kv : ini.Variables(section)) {
            if (kv.first.compare(0, named.size(), named) == 0 && kv.first.size() > named.size()) {
                names.push_back(hal_name_part(kv.first.substr(named.size())));
            } else if (kv.first == plain) {
                char buf[16];
                snprintf(buf, sizeof buf, "%02d", index++);
                names.push_back(buf);
            }
        }
    };
    if (ini.HasSection("MDI_COMMAND_LIST")) scan("MDI_COMMAND_LIST", "MDI_COMMAND_", "MDI_COMMAND");
    if (ini.HasSection("MACROS")) scan("MACROS", "MACRO_COMMAND_", "MACRO");
    else scan("DISPLAY", "MACRO_COMMAND_", "MACRO");
    return names;
}

// Joint counts, axes, spindles, homing sequence.
bool read_machine(const IniFile &ini, HaluiConfig &cfg)
{
    if (!read_int(ini, "KINS", "JOINTS", 1, EMCMOT_MAX_JOINTS, true, &cfg.joints)) return false;
    if (!read_int(ini, "TRAJ", "SPINDLES", 1, EMCMOT_MAX_SPINDLES, false, &cfg.spindles)) return false;
    cfg.axis_mask = axis_mask(ini);
    for (int j = 0; j < cfg.joints; j++)
        if (ini.Find("HOME_SEQUENCE", "JOINT_" + std::to_string(j))) cfg.home_sequence = true;
    if (std::optional<double> u = ini.FindLinearUnits("LINEAR_UNITS", "TRAJ")) cfg.units_per_mm = *u;
    if (ini.Find("MAX_LINEAR_VELOCITY", "TRAJ")) read_real(ini, "TRAJ", "MAX_LINEAR_VELOCITY", &cfg.max_velocity);
    else read_real(ini, "TRAJ", "MAX_VELOCITY", &cfg.max_velocity);
    return true;
}

} // namespace

// Read everything halui needs from the INI file.
bool halui_read_config(const std::string &ini_path, HaluiConfig &cfg)
{
    IniFile ini;
    if (!ini.Open(ini_path)) {
        fprintf(stderr, "halui: %s: %s\n", ini_path.c_str(), ini.ErrorText().c_str());
        return false;
    }
    cfg.ini_path = ini_path;
    std::string why;
    cfg.nml_file = emc_nml_file_for_ini(ini_path, &why);
    if (cfg.nml_file.empty()) {
        fprintf(stderr, "halui: %s\n", why.c_str());
        return false;
    }
    if (!read_machine(ini, cfg)) return false;
    read_real(ini, "DISPLAY", "MAX_FEED_OVERRIDE", &cfg.max_feed_override);
    read_real(ini, "DISPLAY", "MAX_RAPID_OVERRIDE", &cfg.max_rapid_override);
    read_real(ini, "DISPLAY", "MIN_SPINDLE_OVERRIDE", &cfg.min_spindle_override);
    read_real(ini, "DISPLAY", "MAX_SPINDLE_OVERRIDE", &cfg.max_spindle_override);
    read_real(ini, "DISPLAY", "DEFAULT_SPINDLE_SPEED", &cfg.default_spindle_speed);
    cfg.mdi_commands = ini.FindAll("MDI_COMMAND", "HALUI");
    if (cfg.mdi_commands.size() > static_cast<size_t>(HALUI_MAX_MDI)) {
        fprintf(stderr, "halui: %s: %zu [HALUI]MDI_COMMAND entries; only the first %d get pins\n",
                ini_path.c_str(), cfg.mdi_commands.size(), HALUI_MAX_MDI);
        cfg.mdi_commands.resize(HALUI_MAX_MDI);
    }
    cfg.gui_mdi_names = gui_command_names(ini);
    return true;
}
