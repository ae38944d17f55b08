// canon.hh: the canonical machining interface (LinuxCNC's canonical machining functions) the interpreter calls; task, rs274 and previews implement it.
#ifndef OPENEMC_RS274NGC_CANON_HH
#define OPENEMC_RS274NGC_CANON_HH

#include <string>
#include <vector>

enum CanonPlane { CANON_PLANE_XY = 1, CANON_PLANE_YZ, CANON_PLANE_XZ,
                  CANON_PLANE_UV, CANON_PLANE_VW, CANON_PLANE_UW };
enum CanonUnits { CANON_UNITS_INCHES = 1, CANON_UNITS_MM, CANON_UNITS_CM };
enum CanonMotionMode { CANON_EXACT_STOP = 1, CANON_EXACT_PATH, CANON_CONTINUOUS };
enum CanonDirection { CANON_STOPPED = 1, CANON_CLOCKWISE, CANON_COUNTERCLOCKWISE };
enum CanonFeedReference { CANON_WORKPIECE = 1, CANON_XYZ };
enum CanonSide { CANON_SIDE_RIGHT = 1, CANON_SIDE_LEFT, CANON_SIDE_OFF };
enum CanonAxis { CANON_AXIS_X = 1, CANON_AXIS_Y, CANON_AXIS_Z, CANON_AXIS_A,
                 CANON_AXIS_B, CANON_AXIS_C, CANON_AXIS_U, CANON_AXIS_V, CANON_AXIS_W };

// A 9-axis pose X Y Z A B C U V W.
struct CanonPose {
    double x = 0, y = 0, z = 0, a = 0, b = 0, c = 0, u = 0, v = 0, w = 0;
};

// One tool-table entry (tool data index = position in the table, 0 = spindle).
struct CanonTool {
    int toolno = -1;
    int pocketno = 0;
    CanonPose offset;
    double diameter = 0, frontangle = 0, backangle = 0;
    int orientation = 0;
};

// One NURBS control point for G5.2/G5.3.
struct CanonNurbsPoint {
    double x = 0, y = 0, weight = 1;
};

// Abstract consumer of canonical calls; every method maps 1:1 to a LinuxCNC canon call.
class Canon {
public:
    virtual ~Canon() = default;

    // setup / representation
    virtual void init_canon() {}
    virtual void set_g5x_offset(int origin, const CanonPose &p) = 0;
    virtual void set_g92_offset(const CanonPose &p) = 0;
    virtual void set_xy_rotation(double deg) = 0;
    virtual void use_length_units(CanonUnits u) = 0;
    virtual void select_plane(CanonPlane p) = 0;
    virtual void set_feed_reference(CanonFeedReference r) = 0;
    virtual void set_feed_mode(int spindle, int mode) = 0;
    virtual void set_feed_rate(double rate) = 0;
    virtual void set_motion_control_mode(CanonMotionMode m, double tol) = 0;
    virtual void set_planner_mode(int type, double peak_scale) = 0;
    virtual void set_naivecam_tolerance(double tol) = 0;
    virtual void set_traverse_rate(double) {}

    // motion
    virtual void straight_traverse(int line, const CanonPose &p) = 0;
    virtual void straight_feed(int line, const CanonPose &p) = 0;
    virtual void arc_feed(int line, double first_end, double second_end,
                          double first_axis, double second_axis, int rotation,
                          double axis_end, double a, double b, double c,
                          double u, double v, double w) = 0;
    virtual void turn_probe_on() = 0;
    virtual void turn_probe_off() = 0;
    virtual void straight_probe(int line, const CanonPose &p, int type) = 0;
    virtual void rigid_tap(int line, double x, double y, double z, double scale) = 0;
    virtual void dwell(double seconds) = 0;
    virtual void nurbs_g5_feed(int line, const std::vector<CanonNurbsPoint> &pts,
                               unsigned order, CanonPlane plane) = 0;
    virtual void start_speed_feed_synch(int spindle, double feed_per_rev, bool velocity_mode) = 0;
    virtual void stop_speed_feed_synch() = 0;
    virtual void finish() = 0;
    virtual void on_reset() = 0;

    // spindle and coolant
    virtual void set_spindle_mode(int spindle, double css_max) = 0;
    virtual void set_spindle_speed(int spindle, double speed) = 0;
    virtual void start_spindle_clockwise(int spindle) = 0;
    virtual void start_spindle_counterclockwise(int spindle) = 0;
    virtual void stop_spindle_turning(int spindle) = 0;
    virtual void orient_spindle(int spindle, double angle, int mode) = 0;
    virtual void wait_spindle_orient_complete(int spindle, double timeout) = 0;
    virtual void mist_on() = 0;
    virtual void mist_off() = 0;
    virtual void flood_on() = 0;
    virtual void flood_off() = 0;

    // tools
    virtual void select_tool(int toolno) = 0;
    virtual void change_tool() = 0;
    virtual void change_tool_number(int index) = 0;
    virtual void reload_tooldata() = 0;
    virtual void set_tool_table_entry(int index, const CanonTool &t) = 0;
    virtual void use_tool_length_offset(const CanonPose &p) = 0;

    // overrides
    virtual void enable_feed_override() = 0;
    virtual void disable_feed_override() = 0;
    virtual void enable_speed_override(int spindle) = 0;
    virtual void disable_speed_override(int spindle) = 0;
    virtual void enable_adaptive_feed() = 0;
    virtual void disable_adaptive_feed() = 0;
    virtual void enable_feed_hold() = 0;
    virtual void disable_feed_hold() = 0;

    // I/O
    virtual void set_motion_output_bit(int n) = 0;
    virtual void clear_motion_output_bit(int n) = 0;
    virtual void set_aux_output_bit(int n) = 0;
    virtual void clear_aux_output_bit(int n) = 0;
    virtual void set_motion_output_value(int n, double v) = 0;
    virtual void set_aux_output_value(int n, double v) = 0;
    virtual int wait_input(int index, int input_type, int wait_type, double timeout) = 0;
    virtual void lock_rotary(int, int) {}
    virtual void unlock_rotary(int, int) {}

    // text and program control
    virtual void comment(const std::string &text) = 0;
    // CANON_ERROR (from embedded Python): an operator error message; ignored by consumers without one
    virtual void canon_error(const std::string &) {}
    virtual void message(const std::string &text) = 0;
    virtual void log(const std::string &text) = 0;
    virtual void logopen(const std::string &name) = 0;
    virtual void logappend(const std::string &name) = 0;
    virtual void logclose() = 0;
    virtual void program_stop() = 0;
    virtual void optional_program_stop() = 0;
    virtual void pallet_shuttle() = 0;
    virtual void program_end() = 0;
    virtual void set_block_delete(bool) {}
    virtual void set_optional_program_stop(bool) {}
    virtual void update_tag(int) {}

    // queries (GET_EXTERNAL_*), read by the interpreter on synch
    virtual CanonPose get_external_position() = 0;
    virtual CanonPose get_external_probe_position() = 0;
    virtual double get_external_probe_tripped_value() = 0;
    virtual double get_external_length_units() = 0;
    virtual CanonUnits get_external_length_unit_type() = 0;
    virtual CanonMotionMode get_external_motion_control_mode() = 0;
    virtual double get_external_motion_control_tolerance() = 0;
    virtual double get_external_motion_control_naivecam_tolerance() = 0;
    virtual int get_external_tool_slot() = 0;
    virtual int get_external_selected_tool_slot() = 0;
    virtual int get_external_digital_input(int index, int def) = 0;
    virtual double get_external_analog_input(int index, double def) = 0;
    virtual bool get_external_queue_empty() = 0;
    virtual bool get_external_feed_hold_enable() = 0;
    virtual bool get_external_adaptive_feed_enable() = 0;
    virtual int get_external_toolchanger_fault() = 0;
    virtual int get_external_toolchanger_reason() = 0;
};

#endif
