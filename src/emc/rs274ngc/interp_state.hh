// interp_state.hh: the interpreter's setup/modal state, shared with canned cycles and cutter compensation.
#ifndef OPENEMC_RS274NGC_INTERP_STATE_HH
#define OPENEMC_RS274NGC_INTERP_STATE_HH

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "block.hh"
#include "canon.hh"

// Axis indexes into a Pose.
enum AxisIndex { AX_X = 0, AX_Y, AX_Z, AX_A, AX_B, AX_C, AX_U, AX_V, AX_W, AX_COUNT };

// Nine axis values X Y Z A B C U V W.
using Pose = std::array<double, AX_COUNT>;

// An interpreter error; what() is the exact user-visible text (LinuxCNC's texts).
class InterpError : public std::runtime_error {
public:
    explicit InterpError(const std::string &msg) : std::runtime_error(msg) {}
};

// An error detected on another line than the one being executed (a forward search):
// the report names that line.
class InterpErrorAt : public InterpError {
public:
    InterpErrorAt(const std::string &msg, const std::string &line) : InterpError(msg), line_(line) {}
    // the source line the error is about
    const std::string &line() const { return line_; }

private:
    std::string line_;
};

// Round a user-supplied value to an int, clamped to +-1e9 (NaN -> 0), so casts never overflow.
inline int clamp_int(double v)
{
    if (!(v == v)) return 0;
    if (v > 1e9) return 1000000000;
    if (v < -1e9) return -1000000000;
    return (int)(v < 0 ? v - 0.5 : v + 0.5);
}

// Rotate (x, y) counterclockwise by deg degrees about the origin (no change for 0).
inline void rotate_xy(double &x, double &y, double deg)
{
    if (deg == 0.0) return;
    double t = deg * (M_PI / 180.0), c = std::cos(t), s = std::sin(t);
    double rx = x * c - y * s, ry = x * s + y * c;
    x = rx;
    y = ry;
}

// The canon form of a nine-axis pose (X Y Z A B C U V W), used by every emitter of moves.
inline CanonPose to_canon_pose(const Pose &p)
{
    CanonPose c;
    c.x = p[AX_X]; c.y = p[AX_Y]; c.z = p[AX_Z];
    c.a = p[AX_A]; c.b = p[AX_B]; c.c = p[AX_C];
    c.u = p[AX_U]; c.v = p[AX_V]; c.w = p[AX_W];
    return c;
}

// Feed mode (group 5).
enum FeedMode { FEED_UNITS_PER_MINUTE = 0, FEED_INVERSE_TIME = 1, FEED_UNITS_PER_REV = 2 };

// Canned-cycle return mode (group 10).
enum RetractMode { RETRACT_OLD_Z = 0, RETRACT_R_PLANE = 1 };

// Number of numbered parameters (#0 unused .. #5601).
constexpr int PARAM_COUNT = 5602;
// Most spindles a machine may have ([TRAJ]SPINDLES); the state arrays have this size.
constexpr int SPINDLE_COUNT = 8;
// Parameter numbers the cycles and comp code read.
constexpr int PARAM_G28_HOME = 5161;
constexpr int PARAM_G30_HOME = 5181;

// Settings read once from the INI file ([RS274NGC] and friends) or defaulted.
struct InterpSettings {
    double g73_peck_clearance = -1;   // <0: default by initial units
    double g83_peck_clearance = -1;
    double orient_offset = 0;
    bool retain_g43 = false;
    bool disable_g92_persistence = false;
    bool disable_auto_g54 = false;
    bool oword_narg = false;
    bool oword_warnonly = false;
    bool disable_fanuc_style_sub = false;
    bool ini_vars = true;
    bool hal_pin_vars = true;
    bool tool_change_quill_up = false;
    bool tool_change_at_g30 = false;
    bool tool_change_with_spindle_on = false;
    bool random_toolchanger = false;
    bool lazy_close = false;
    int metric_machine = -1;          // _metric_machine
    long loop_limit = 100000000;      // passes of one loop before it counts as runaway (0: none)
    long total_loop_limit = 1000000000; // passes of all loops of one program (0: none)
    std::string program_prefix;
    std::vector<std::string> subroutine_path;
    std::vector<std::string> user_m_path;     // [RS274NGC]USER_M_PATH dirs (M100-M199)
    std::string wizard_root;
    std::string ini_file;
};

// Modal state saved by M70/M73 and restored by M72.
struct SavedModal {
    bool valid = false;
    CanonUnits units = CANON_UNITS_MM;
    CanonPlane plane = CANON_PLANE_XY;
    int comp_code = 400;
    bool distance_incremental = false;
    bool ijk_absolute = false;
    FeedMode feed_mode = FEED_UNITS_PER_MINUTE;
    int origin_index = 1;
    int tlo_code = 490;
    RetractMode retract = RETRACT_R_PLANE;
    bool css_mode = false;
    bool lathe_diameter = false;
    CanonMotionMode control_mode = CANON_CONTINUOUS;
    double tolerance = 0, naivecam_tolerance = 0;
    double feed_rate = 0, speed = 0;
    CanonDirection spindle_dir = CANON_STOPPED;
    bool mist = false, flood = false;
    bool feed_override = true, speed_override = true, adaptive_feed = false, feed_hold = true;
};

// The whole interpreter state. Lengths are in current program units unless noted.
struct InterpState {
    // position and geometry
    Pose current{};                 // tool tip, program coords of the active system
    CanonPlane plane = CANON_PLANE_XY;
    CanonUnits units = CANON_UNITS_MM;
    CanonUnits machine_units = CANON_UNITS_INCHES;  // units of stored parameters / tool table
    double external_length_units = 1.0 / 25.4;      // machine units per mm (the canon's answer)
    bool distance_incremental = false;    // G91
    bool ijk_absolute = false;            // G90.1
    bool lathe_diameter = false;          // G7
    int motion_mode = 800;                // group 1 code ×10 (G80 -> 800)

    // feeds and speeds
    FeedMode feed_mode = FEED_UNITS_PER_MINUTE;
    double feed_rate = 0;
    double speed[SPINDLE_COUNT] = {};
    CanonDirection spindle_dir[SPINDLE_COUNT] = {CANON_STOPPED, CANON_STOPPED, CANON_STOPPED,
                                                 CANON_STOPPED, CANON_STOPPED, CANON_STOPPED,
                                                 CANON_STOPPED, CANON_STOPPED};
    int num_spindles = 1;                 // [TRAJ]SPINDLES
    bool css_mode[SPINDLE_COUNT] = {};    // G96
    double css_max[SPINDLE_COUNT] = {};
    bool mist = false, flood = false;
    bool feed_override = true, speed_override = true, adaptive_feed = false, feed_hold = true;

    // path control (group 13)
    CanonMotionMode control_mode = CANON_CONTINUOUS;
    double tolerance = 0, naivecam_tolerance = 0;

    // offsets (program units)
    int origin_index = 1;                 // 1..9 = G54..G59.3
    Pose origin_offset{};                 // active G5x offset
    Pose axis_offset{};                   // G52/G92 offset
    double rotation_xy = 0;               // degrees
    Pose tool_offset{};                   // active tool length offset
    int tlo_code = 490;                   // 430, 431, 432 or 490

    // canned cycles (sticky words, initial level)
    RetractMode retract = RETRACT_R_PLANE;
    int cycle_last = -1;                  // motion code of the previous cycle block, -1 none
    double cycle_r = 0, cycle_z = 0, cycle_p = 0, cycle_q = 0;
    double cycle_il = 0;                  // initial level
    bool cycle_il_valid = false;
    double peck_clearance_g73 = 1.0, peck_clearance_g83 = 1.0;

    // cutter radius compensation (group 7)
    int comp_code = 400;                  // 400, 410, 411, 420, 421
    CanonSide comp_side = CANON_SIDE_OFF;
    double comp_radius = 0;               // program units
    int comp_orientation = 0;

    // tools: table[0] is the spindle (loaded tool), table[n] as loaded
    std::vector<CanonTool> tools;
    int selected_tool = 0;                // T word (tool number)
    int selected_pocket = -1;             // tool-data index of the prepared tool
    int current_pocket = 0;

    // numbered parameters #1..#5601
    std::vector<double> params = std::vector<double>(PARAM_COUNT, 0.0);

    // sequence info
    int sequence_number = 0;              // file line number of the current block
    std::string line_text;                // the current line as read
    std::string filename;
    int call_level = 0;

    InterpSettings settings;
    SavedModal saved;                     // M70 slot

    // spindle selected by a block's $ word (0 without one); error when not configured
    int spindle_of(const Block &b) const
    {
        int sp = b.has_dollar ? clamp_int(b.dollar) : 0;
        if (sp < 0 || sp >= num_spindles) throw InterpError("Invalid spindle ($) number");
        return sp;
    }
    // value of numbered parameter n
    double param(int n) const { return params[n]; }
    // set numbered parameter n
    void set_param(int n, double v) { params[n] = v; }
    // program units per mm (the divisor LinuxCNC's unit conversion uses after the machine's)
    double units_per_mm_divisor() const
    {
        return units == CANON_UNITS_INCHES ? 25.4 : units == CANON_UNITS_CM ? 10.0 : 1.0;
    }
    // a stored length (machine units: parameters, tool table) in program units, computed as
    // LinuxCNC does (divided by the canon's length units, then by 25.4 for inch programs), so
    // values that round at a 5 print the same
    double user_to_program(double v) const
    {
        return v / external_length_units / units_per_mm_divisor();
    }
    // a program-unit length in machine units (LinuxCNC's inverse arithmetic)
    double program_to_user(double v) const
    {
        return v * external_length_units * units_per_mm_divisor();
    }
    // #5400 / #<_current_tool>: an empty spindle is T0 (non-random) or -1 (random changer)
    int loaded_tool_number() const;
    // #<_current_pocket>: the loaded tool's pocket (random: 0, the spindle), -1 for none
    int loaded_pocket_number() const;
    // #<_selected_pocket>: the prepared tool's pocket, -1 when none is prepared
    int selected_pocket_number() const;
};

#endif
