// sai_canon.hh: the standalone interpreter's Canon: prints every call as LinuxCNC's rs274 does.
#ifndef OPENEMC_RS274NGC_SAI_CANON_HH
#define OPENEMC_RS274NGC_SAI_CANON_HH

#include <cstdio>
#include <string>

#include "canon.hh"

// inch machine's length units per mm as LinuxCNC's standalone interpreter reports them (a
// rounded 1/25.4: conversions of stored inch values land where LinuxCNC's do)
constexpr double SAI_INCH_UNITS_PER_MM = 0.03937007874016;

// Printing canon for rs274 (and the fuzz/bench harnesses with a null stream).
class SaiCanon : public Canon {
public:
    // out: stream for canon lines (nullptr = print nothing); line: current line text
    SaiCanon(FILE *out, const std::string *line) : out_(out), line_(line) {}
    // where the current line text lives (for the N markers)
    void set_line_source(const std::string *line) { line_ = line; }
    // machine units are mm (rs274 -i with [TRAJ]LINEAR_UNITS = mm)
    void set_machine_mm(bool mm) { machine_mm_ = mm; }

    void set_g5x_offset(int origin, const CanonPose &p) override;
    void set_g92_offset(const CanonPose &p) override;
    void set_xy_rotation(double deg) override;
    void use_length_units(CanonUnits u) override;
    void select_plane(CanonPlane p) override;
    void set_feed_reference(CanonFeedReference r) override;
    void set_feed_mode(int spindle, int mode) override;
    void set_feed_rate(double rate) override;
    void set_motion_control_mode(CanonMotionMode m, double tol) override;
    void set_planner_mode(int type, double peak_scale) override;
    void set_naivecam_tolerance(double tol) override;
    void straight_traverse(int line, const CanonPose &p) override;
    void straight_feed(int line, const CanonPose &p) override;
    void arc_feed(int line, double first_end, double second_end, double first_axis,
                  double second_axis, int rotation, double axis_end, double a, double b,
                  double c, double u, double v, double w) override;
    void turn_probe_on() override;
    void turn_probe_off() override;
    void straight_probe(int line, const CanonPose &p, int type) override;
    void rigid_tap(int line, double x, double y, double z, double scale) override;
    void dwell(double seconds) override;
    void nurbs_g5_feed(int line, const std::vector<CanonNurbsPoint> &pts, unsigned order,
                       CanonPlane plane) override;
    void start_speed_feed_synch(int spindle, double feed_per_rev, bool velocity_mode) override;
    void stop_speed_feed_synch() override;
    void finish() override;
    void on_reset() override;
    void set_spindle_mode(int spindle, double css_max) override;
    void set_spindle_speed(int spindle, double speed) override;
    void start_spindle_clockwise(int spindle) override;
    void start_spindle_counterclockwise(int spindle) override;
    void stop_spindle_turning(int spindle) override;
    void orient_spindle(int spindle, double angle, int mode) override;
    void wait_spindle_orient_complete(int spindle, double timeout) override;
    void mist_on() override;
    void mist_off() override;
    void flood_on() override;
    void flood_off() override;
    void select_tool(int toolno) override;
    void change_tool() override;
    void change_tool_number(int index) override;
    void reload_tooldata() override;
    void set_tool_table_entry(int index, const CanonTool &t) override;
    void use_tool_length_offset(const CanonPose &p) override;
    void enable_feed_override() override;
    void disable_feed_override() override;
    void enable_speed_override(int spindle) override;
    void disable_speed_override(int spindle) override;
    void enable_adaptive_feed() override;
    void disable_adaptive_feed() override;
    void enable_feed_hold() override;
    void disable_feed_hold() override;
    void set_motion_output_bit(int n) override;
    void clear_motion_output_bit(int n) override;
    void set_aux_output_bit(int n) override;
    void clear_aux_output_bit(int n) override;
    void set_motion_output_value(int n, double v) override;
    void set_aux_output_value(int n, double v) override;
    int wait_input(int, int, int, double) override { return 0; }
    void comment(const std::string &text) override;
    void message(const std::string &text) override;
    void canon_error(const std::string &text) override;
    void log(const std::string &text) override;
    void logopen(const std::string &name) override;
    void logappend(const std::string &name) override;
    void logclose() override;
    void program_stop() override;
    void optional_program_stop() override;
    void pallet_shuttle() override;
    void program_end() override;

    CanonPose get_external_position() override { return pos_; }
    CanonPose get_external_probe_position() override { return probe_; }
    double get_external_probe_tripped_value() override { return 0; }
    double get_external_length_units() override { return machine_mm_ ? 1.0 : SAI_INCH_UNITS_PER_MM; }
    CanonUnits get_external_length_unit_type() override
    {
        return machine_mm_ ? CANON_UNITS_MM : CANON_UNITS_INCHES;
    }
    CanonMotionMode get_external_motion_control_mode() override { return CANON_CONTINUOUS; }
    double get_external_motion_control_tolerance() override { return 0; }
    double get_external_motion_control_naivecam_tolerance() override { return 0; }
    int get_external_tool_slot() override { return 1; }
    int get_external_selected_tool_slot() override { return 0; }
    int get_external_digital_input(int, int def) override { return def; }
    double get_external_analog_input(int, double def) override { return def; }
    bool get_external_queue_empty() override { return true; }
    bool get_external_feed_hold_enable() override { return true; }
    bool get_external_adaptive_feed_enable() override { return false; }
    int get_external_toolchanger_fault() override { return 0; }
    int get_external_toolchanger_reason() override { return 0; }

private:
    void emit(const char *text);
    void emit(const char *text, size_t len);
    static int counter_text(char *buf, long v);
    void emitf(const char *fmt, ...) __attribute__((format(printf, 2, 3)));
    void emit_pose(const char *name, int count, const CanonPose &p, const char *sep);
    void emit_values(const char *name, const double *v, int count, const char *sep);
    void track(const CanonPose &p);

    FILE *out_;
    const std::string *line_;
    long counter_ = 0;
    bool machine_mm_ = false;
    CanonUnits units_ = CANON_UNITS_MM;
    CanonPose pos_, probe_;
    char line_buf_[1024];
};

// Room for any "%.4f" of a double (up to 309 integer digits, sign, point, 4 decimals).
constexpr int FIXED4_MAX = 330;

// Append v formatted like printf("%.4f") to buf; returns the new end.
char *format_fixed4(char *buf, double v);

#endif
