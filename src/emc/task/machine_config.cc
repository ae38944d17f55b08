// machine_config.cc: reading task's INI keys with LinuxCNC's defaults; fatal problems are collected as messages.
#include "machine_config.hh"
#include "task_canon.hh"

#include <cctype>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <sstream>

#include "inifile.hh"

namespace {

const char AXIS_LETTERS[] = "XYZABCUVW";

// Typed lookups with defaults; IniFile itself reports malformed values (default used then).
struct Reader {
    const IniFile &ini;
    std::vector<std::string> *errors;

    double real(const std::string &sec, const std::string &key, double def) const
    {
        auto v = ini.FindReal(key, sec);
        return v ? *v : def;
    }
    long long integer(const std::string &sec, const std::string &key, long long def) const
    {
        auto v = ini.FindInt(key, sec);
        return v ? *v : def;
    }
    bool boolean(const std::string &sec, const std::string &key, bool def) const
    {
        auto v = ini.FindBool(key, sec);
        return v ? *v : def;
    }
    std::string text(const std::string &sec, const std::string &key, const std::string &def = "") const
    {
        auto v = ini.Find(key, sec);
        return v ? *v : def;
    }
    // "file:line: [SEC]KEY: what" when the key exists, "[SEC]KEY: what" otherwise.
    void fail(const std::string &sec, const std::string &key, const std::string &what) const
    {
        const IniEntry *e = ini.FindEntry(key, sec);
        std::string where = e ? e->file + ":" + std::to_string(e->line) + ": " : ini.Path() + ": ";
        errors->push_back(where + "[" + sec + "]" + key + ": " + what);
    }
};

// Directory of path ("." when none).
std::string dir_of(const std::string &path)
{
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

// path made absolute against dir (kept when already absolute or empty).
std::string resolve(const std::string &dir, const std::string &path)
{
    if (path.empty() || path[0] == '/') return path;
    if (path.compare(0, 2, "~/") == 0 && getenv("HOME")) return std::string(getenv("HOME")) + path.substr(1);
    return dir + "/" + path;
}

void read_traj(const Reader &r, MachineConfig &c)
{
    auto lu = r.ini.Find("LINEAR_UNITS", "TRAJ");
    if (lu) {
        auto v = IniFile::MapLinearUnits(*lu);
        if (!v) r.fail("TRAJ", "LINEAR_UNITS", "must be one of mm, metric, in, inch, imperial (got '" + *lu + "')");
        else c.linear_units = *v;
    }
    auto au = r.ini.Find("ANGULAR_UNITS", "TRAJ");
    if (au) {
        auto v = IniFile::MapAngularUnits(*au);
        if (!v) r.fail("TRAJ", "ANGULAR_UNITS", "must be one of deg, degree, rad, radian, grad, gon (got '" + *au + "')");
        else c.angular_units = *v;
    }
    std::string coords = r.text("TRAJ", "COORDINATES", "X Y Z");
    c.axis_mask = 0;
    for (char ch : coords) {
        const char *p = strchr(AXIS_LETTERS, toupper((unsigned char)ch));
        if (ch && p) c.axis_mask |= 1 << (p - AXIS_LETTERS);
    }
    c.spindles = (int)r.integer("TRAJ", "SPINDLES", 1);
    if (c.spindles < 1 || c.spindles > EMCMOT_MAX_SPINDLES) {
        r.fail("TRAJ", "SPINDLES", "must be 1.." + std::to_string(EMCMOT_MAX_SPINDLES));
        c.spindles = 1;
    }
    c.default_linear_velocity = r.real("TRAJ", "DEFAULT_LINEAR_VELOCITY", 1.0);
    c.max_linear_velocity = r.real("TRAJ", "MAX_LINEAR_VELOCITY", 1e99);
    c.max_linear_acceleration = r.real("TRAJ", "MAX_LINEAR_ACCELERATION", 1e99);
    c.default_linear_acceleration = r.real("TRAJ", "DEFAULT_LINEAR_ACCELERATION", 1e99);
    if (c.default_linear_acceleration > c.max_linear_acceleration)
        c.default_linear_acceleration = c.max_linear_acceleration;
    c.max_linear_jerk = r.real("TRAJ", "MAX_LINEAR_JERK", 1e9);
    c.planner_type = (int)r.integer("TRAJ", "PLANNER_TYPE", 0);
    if (c.planner_type < 0 || c.planner_type > 1) c.planner_type = 0;
    if (c.planner_type == 1 && c.max_linear_jerk < 1.0) {
        fprintf(stderr, "[TRAJ]PLANNER_TYPE = 1 (S-curve) requires [TRAJ]MAX_LINEAR_JERK >= 1.0 (got %g); "
                "using trapezoidal planner\n", c.max_linear_jerk);
        c.planner_type = 0;
    }
    c.scurve_peak_scale = r.real("TRAJ", "SCURVE_PEAK_SCALE", 1.0);
    c.no_force_homing = r.boolean("TRAJ", "NO_FORCE_HOMING", false);
    c.arc_blend_enable = r.boolean("TRAJ", "ARC_BLEND_ENABLE", true);
    c.arc_blend_fallback_enable = r.boolean("TRAJ", "ARC_BLEND_FALLBACK_ENABLE", false);
    c.arc_blend_optimization_depth = (int)r.integer("TRAJ", "ARC_BLEND_OPTIMIZATION_DEPTH", 50);
    c.arc_blend_gap_cycles = r.real("TRAJ", "ARC_BLEND_GAP_CYCLES", 4);
    c.arc_blend_ramp_freq = r.real("TRAJ", "ARC_BLEND_RAMP_FREQ", 100);
    c.arc_blend_kink_ratio = r.real("TRAJ", "ARC_BLEND_KINK_RATIO", 0.1);
    c.no_probe_jog_error = r.boolean("TRAJ", "NO_PROBE_JOG_ERROR", false);
    c.no_probe_home_error = r.boolean("TRAJ", "NO_PROBE_HOME_ERROR", false);
    std::istringstream home(r.text("TRAJ", "HOME"));
    std::string tok;
    for (int i = 0; i < EMCMOT_MAX_AXIS && home >> tok; i++) {
        char *end = nullptr;
        double v = strtod(tok.c_str(), &end);
        if (!end || *end) r.fail("TRAJ", "HOME", "Invalid value '" + tok + "' for axis " + std::to_string(i) + " in homePose");
        c.world_home[i] = v;
    }
}

void read_joint(const Reader &r, MachineConfig &c, int n)
{
    std::string s = "JOINT_" + std::to_string(n);
    JointConfig &j = c.joint[n];
    auto type = r.ini.Find("TYPE", s);
    if (type) {
        auto t = IniFile::MapJointType(*type);
        if (!t) r.fail(s, "TYPE", "must be LINEAR or ANGULAR (got '" + *type + "')");
        else j.type = *t;
    }
    j.units = j.type == 2 ? c.angular_units : c.linear_units;
    j.min_limit = r.real(s, "MIN_LIMIT", -1e99);
    j.max_limit = r.real(s, "MAX_LIMIT", 1e99);
    j.max_velocity = r.real(s, "MAX_VELOCITY", 1.0);
    j.max_acceleration = r.real(s, "MAX_ACCELERATION", 1.0);
    j.max_jerk = r.real(s, "MAX_JERK", 0);
    j.backlash = r.real(s, "BACKLASH", 0);
    j.ferror = r.real(s, "FERROR", 1.0);
    j.min_ferror = r.real(s, "MIN_FERROR", j.ferror);
    j.home = r.real(s, "HOME", 0);
    j.home_offset = r.real(s, "HOME_OFFSET", 0);
    j.home_search_vel = r.real(s, "HOME_SEARCH_VEL", 0);
    j.home_latch_vel = r.real(s, "HOME_LATCH_VEL", 0);
    j.home_final_vel = r.real(s, "HOME_FINAL_VEL", -1);
    j.home_use_index = r.boolean(s, "HOME_USE_INDEX", false);
    j.home_ignore_limits = r.boolean(s, "HOME_IGNORE_LIMITS", false);
    j.home_is_shared = r.boolean(s, "HOME_IS_SHARED", false);
    j.home_index_no_encoder_reset = r.boolean(s, "HOME_INDEX_NO_ENCODER_RESET", false);
    j.home_absolute_encoder = (int)r.integer(s, "HOME_ABSOLUTE_ENCODER", 0);
    if (j.home_absolute_encoder < 0 || j.home_absolute_encoder > 2) {
        r.fail(s, "HOME_ABSOLUTE_ENCODER", "must be 0, 1 or 2");
        j.home_absolute_encoder = 0;
    }
    j.home_sequence = (int)r.integer(s, "HOME_SEQUENCE", 999);
    j.volatile_home = r.boolean(s, "VOLATILE_HOME", false);
    j.locking_indexer = r.boolean(s, "LOCKING_INDEXER", false);
    j.comp_file = resolve(dir_of(c.ini_path), r.text(s, "COMP_FILE"));
    j.comp_file_type = (int)r.integer(s, "COMP_FILE_TYPE", 0);
}

void read_axis(const Reader &r, MachineConfig &c, int n)
{
    std::string s = std::string("AXIS_") + AXIS_LETTERS[n];
    AxisConfig &a = c.axis[n];
    a.min_limit = r.real(s, "MIN_LIMIT", -1e99);
    a.max_limit = r.real(s, "MAX_LIMIT", 1e99);
    a.max_velocity = r.real(s, "MAX_VELOCITY", 1.0);
    a.max_acceleration = r.real(s, "MAX_ACCELERATION", 1.0);
    a.max_jerk = r.real(s, "MAX_JERK", 0);
    a.offset_av_ratio = r.real(s, "OFFSET_AV_RATIO", 0);
    if (a.offset_av_ratio < 0 || a.offset_av_ratio > 0.9) {
        fprintf(stderr, "Invalid: [%s]OFFSET_AV_RATIO=%g; using: [%s]OFFSET_AV_RATIO= 0.10000\n",
                s.c_str(), a.offset_av_ratio, s.c_str());
        a.offset_av_ratio = 0.1;
    }
    a.locking_joint = (int)r.integer(s, "LOCKING_INDEXER_JOINT", -1);
}

void read_spindle(const Reader &r, MachineConfig &c, int n)
{
    std::string s = "SPINDLE_" + std::to_string(n);
    SpindleConfig &p = c.spindle[n];
    p.max_pos = r.real(s, "MAX_FORWARD_VELOCITY", 1e99);
    p.min_pos = r.real(s, "MIN_FORWARD_VELOCITY", 0);
    p.max_neg = -r.real(s, "MAX_REVERSE_VELOCITY", p.max_pos);
    p.min_neg = -r.real(s, "MIN_REVERSE_VELOCITY", p.min_pos);
    if (p.min_neg == 0) p.min_neg = 0;
    p.increment = r.real(s, "INCREMENT", 100);
}

// [EMCIO]TOOL_CHANGE_POSITION: X Y Z [A B C [U V W]] machine coordinates M6 moves to first.
void read_tool_change_position(const Reader &r, MachineConfig &c)
{
    std::istringstream in(r.text("EMCIO", "TOOL_CHANGE_POSITION"));
    std::string tok;
    int n = 0;
    while (in >> tok) {
        char *end = nullptr;
        double v = strtod(tok.c_str(), &end);
        if (!end || *end || n >= EMCMOT_MAX_AXIS) {
            r.fail("EMCIO", "TOOL_CHANGE_POSITION", "needs 3, 6 or 9 numbers (got '" + tok + "')");
            return;
        }
        c.tool_change_position[n++] = v;
    }
    if (n != 0 && n != 3 && n != 6 && n != 9) {
        r.fail("EMCIO", "TOOL_CHANGE_POSITION", "needs 3, 6 or 9 numbers, not " + std::to_string(n));
        return;
    }
    c.tool_change_axes = n;
}

void read_task(const Reader &r, MachineConfig &c)
{
    std::string dir = dir_of(c.ini_path);
    c.cycle_time = r.real("TASK", "CYCLE_TIME", 0.1);
    c.interp_max_len = (int)r.integer("TASK", "INTERP_MAX_LEN", 1000);
    if (c.interp_max_len < 1) c.interp_max_len = 1000;
    c.io_error = r.text("TASK", "IO_ERROR", c.io_error);
    c.comm_timeout = r.real("EMCMOT", "COMM_TIMEOUT", 1.0);
    c.shmem_key = (int)r.integer("EMCMOT", "SHMEM_KEY", 100);
    c.max_feed_override = r.real("DISPLAY", "MAX_FEED_OVERRIDE", 1.0);
    std::string tt = r.text("EMCIO", "TOOL_TABLE");
    c.tool_table = resolve(dir, tt);
    c.random_toolchanger = r.boolean("EMCIO", "RANDOM_TOOLCHANGER", false);
    read_tool_change_position(r, c);
    c.program_prefix = resolve(dir, r.text("DISPLAY", "PROGRAM_PREFIX"));
    c.on_abort_command = r.text("RS274NGC", "ON_ABORT_COMMAND");
    c.startup_code = r.text("RS274NGC", "RS274NGC_STARTUP_CODE");
}

}  // namespace

bool machine_config_read(const std::string &ini_path, MachineConfig &c, std::vector<std::string> *errors)
{
    IniFile ini;
    if (!ini.Open(ini_path)) {
        errors->push_back(ini_path + ": " + ini.ErrorText());
        return false;
    }
    Reader r{ini, errors};
    c.ini_path = ini_path;
    auto joints = ini.FindInt("JOINTS", "KINS");
    if (!joints) r.fail("KINS", "JOINTS", ini.Find("JOINTS", "KINS") ? "not an integer" : "missing");
    else if (*joints < 1 || *joints > EMCMOT_MAX_JOINTS) r.fail("KINS", "JOINTS", "must be 1..16");
    else c.joints = (int)*joints;
    read_traj(r, c);
    c.joint.assign(c.joints, JointConfig());
    for (int j = 0; j < c.joints; j++) read_joint(r, c, j);
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++)
        if (c.axis_mask & (1 << a)) read_axis(r, c, a);
    for (int s = 0; s < c.spindles; s++) read_spindle(r, c, s);
    read_task(r, c);
    return errors->empty();
}

canon_axis_limits_t machine_axis_limits(const MachineConfig &c)
{
    canon_axis_limits_t lim;
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        double keep = 1.0 - c.axis[a].offset_av_ratio;
        lim.vel[a] = c.axis[a].max_velocity * keep;
        lim.acc[a] = c.axis[a].max_acceleration * keep;
        lim.jerk[a] = c.axis[a].max_jerk;
    }
    return lim;
}

CanonConfig machine_canon_config(const MachineConfig &c)
{
    CanonConfig cc;
    cc.linear_units = c.linear_units;
    cc.angular_units = c.angular_units;
    cc.axis_mask = c.axis_mask;
    cc.spindles = c.spindles;
    cc.limits = machine_axis_limits(c);
    cc.tool_change_axes = c.tool_change_axes;
    for (int i = 0; i < 9; i++) cc.tool_change_position[i] = c.tool_change_position[i];
    return cc;
}
