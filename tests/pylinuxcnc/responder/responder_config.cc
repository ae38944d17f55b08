// responder_config.cc: the responder's INI settings and its LinuxCNC-format tool table.
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "inifile.hh"
#include "responder.hh"

namespace {

// Folder of a path.
std::string dir_of(const std::string &path)
{
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

// First present real of several keys in a section.
double real_of(const IniFile &ini, const char *section, std::initializer_list<const char *> keys,
               double fallback)
{
    for (const char *key : keys)
        if (auto v = ini.FindReal(key, section)) return *v;
    return fallback;
}

// Axis mask of [TRAJ]COORDINATES (letters XYZABCUVW).
int mask_of(const std::string &coords)
{
    static const char letters[] = "XYZABCUVW";
    int mask = 0;
    for (char c : coords) {
        const char *hit = strchr(letters, toupper(static_cast<unsigned char>(c)));
        if (hit && *hit) mask |= 1 << (hit - letters);
    }
    return mask;
}

// Store one word of a tool-table line into the entry; false for an unknown letter.
bool tool_word(char letter, double value, tooldata_entry_t &e)
{
    double *offsets[] = {&e.offset.tran.x, &e.offset.tran.y, &e.offset.tran.z, &e.offset.a,
                         &e.offset.b, &e.offset.c, &e.offset.u, &e.offset.v, &e.offset.w};
    const char *axes = "XYZABCUVW";
    const char *hit = strchr(axes, letter);
    if (hit && *hit) *offsets[hit - axes] = value;
    else if (letter == 'T') e.toolno = static_cast<int>(value);
    else if (letter == 'P') e.pocketno = static_cast<int>(value);
    else if (letter == 'D') e.diameter = value;
    else if (letter == 'I') e.frontangle = value;
    else if (letter == 'J') e.backangle = value;
    else if (letter == 'Q') e.orientation = static_cast<int>(value);
    else return false;
    return true;
}

// Parse one tool-table line; 1 entry, 0 blank, -1 error (printed).
int tool_line(const std::string &path, int lineno, std::string line, tooldata_entry_t &e)
{
    e = tooldata_empty_entry();
    size_t semi = line.find(';');
    if (semi != std::string::npos) {
        std::string comment = line.substr(semi + 1);
        while (!comment.empty() && isspace(static_cast<unsigned char>(comment.back()))) comment.pop_back();
        size_t start = comment.find_first_not_of(" \t");
        emc_set_text(e.comment, start == std::string::npos ? "" : comment.c_str() + start);
        line.resize(semi);
    }
    std::istringstream words(line);
    std::string w;
    bool any = false;
    while (words >> w) {
        char letter = static_cast<char>(toupper(static_cast<unsigned char>(w[0])));
        char *end = nullptr;
        double value = strtod(w.c_str() + 1, &end);
        if (w.size() < 2 || *end || !tool_word(letter, value, e)) {
            fprintf(stderr, "%s:%d: bad tool-table word '%s'\n", path.c_str(), lineno, w.c_str());
            return -1;
        }
        any = true;
    }
    return any ? 1 : 0;
}

} // namespace

// Read the settings the responder uses.
bool responder_load_config(const std::string &path, ResponderConfig &cfg)
{
    IniFile ini;
    if (!ini.Open(path)) return false;
    ini.SetQuiet(true);
    std::string err;
    cfg.ini_path = path;
    cfg.nml_file = emc_nml_file_for_ini(path, &err);
    cfg.joints = static_cast<int>(ini.FindInt("JOINTS", "KINS").value_or(3));
    cfg.spindles = static_cast<int>(ini.FindInt("SPINDLES", "TRAJ").value_or(1));
    cfg.axis_mask = mask_of(ini.Find("COORDINATES", "TRAJ").value_or("XYZ"));
    cfg.linear_units = ini.FindLinearUnits("LINEAR_UNITS", "TRAJ").value_or(1.0);
    cfg.angular_units = ini.FindAngularUnits("ANGULAR_UNITS", "TRAJ").value_or(1.0);
    cfg.cycle_s = ini.FindReal("CYCLE_TIME", "TASK").value_or(0.001);
    cfg.servo_s = ini.FindReal("SERVO_PERIOD", "EMCMOT").value_or(1000000) * 1e-9;
    cfg.max_velocity = real_of(ini, "TRAJ", {"MAX_LINEAR_VELOCITY", "MAX_VELOCITY"}, 1.0);
    cfg.max_acceleration = real_of(ini, "TRAJ", {"MAX_LINEAR_ACCELERATION", "MAX_ACCELERATION"}, 1.0);
    cfg.default_velocity = real_of(ini, "TRAJ", {"DEFAULT_LINEAR_VELOCITY", "DEFAULT_VELOCITY"}, 1.0);
    cfg.default_acceleration =
        real_of(ini, "TRAJ", {"DEFAULT_LINEAR_ACCELERATION", "DEFAULT_ACCELERATION"}, 1.0);
    cfg.no_force_homing = ini.FindBool("NO_FORCE_HOMING", "TRAJ").value_or(false);
    if (auto table = ini.Find("TOOL_TABLE", "EMCIO"))
        cfg.tool_table = (*table)[0] == '/' ? *table : dir_of(path) + "/" + *table;
    if (cfg.nml_file.empty() || cfg.joints < 1 || cfg.joints > EMCMOT_MAX_JOINTS ||
        cfg.spindles < 1 || cfg.spindles > EMCMOT_MAX_SPINDLES || !(cfg.cycle_s > 0)) {
        fprintf(stderr, "nml_responder: %s: bad JOINTS, SPINDLES or CYCLE_TIME %s\n", path.c_str(),
                err.c_str());
        return false;
    }
    return true;
}

// Load the tool table: entry 0 is the spindle (empty), then one entry per line.
bool responder_load_tools(Machine &m, const std::string &path)
{
    std::ifstream in(path);
    if (!in) {
        fprintf(stderr, "nml_responder: cannot open tool table %s\n", path.c_str());
        return false;
    }
    std::vector<tooldata_entry_t> table(1, tooldata_empty_entry());
    std::string line;
    int lineno = 0;
    while (std::getline(in, line)) {
        tooldata_entry_t e;
        int rc = tool_line(path, ++lineno, line, e);
        if (rc < 0) return false;
        if (rc > 0 && table.size() < TOOLDATA_MAX_ENTRIES) table.push_back(e);
    }
    m.tool_table = table;
    responder_publish_tools(m);
    return true;
}

// Publish the table (entry 0 follows the tool in the spindle).
void responder_publish_tools(Machine &m)
{
    if (m.tool_table.empty()) m.tool_table.push_back(tooldata_empty_entry());
    tooldata_publish(m.tools, m.tool_table.data(), static_cast<int>(m.tool_table.size()));
}
