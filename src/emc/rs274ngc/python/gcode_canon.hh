// gcode_canon.hh: the canon of the `gcode` module: forwards the interpreter's calls to a Python canon object.
#ifndef OPENEMC_RS274NGC_GCODE_CANON_HH
#define OPENEMC_RS274NGC_GCODE_CANON_HH

#include "../canon.hh"
#include "py_util.hh"

class Interp;

// Canon that calls the methods previews implement (straight_feed, arc_feed, next_line, ...).
class PyCanon : public Canon {
public:
    explicit PyCanon(PyObject *canon) : canon_(canon) {}
    // the interpreter whose state next_line() reports
    void attach(Interp *interp) { interp_ = interp; }
    // true when a Python call failed (its exception is pending; parse() re-raises it)
    bool failed() const { return failed_; }

    void set_g5x_offset(int origin, const CanonPose &p) override;
    void set_g92_offset(const CanonPose &p) override;
    void set_xy_rotation(double deg) override;
    void use_length_units(CanonUnits) override {}
    void select_plane(CanonPlane p) override;
    void set_feed_reference(CanonFeedReference) override {}
    void set_feed_mode(int, int) override {}
    void set_feed_rate(double rate) override;
    void set_motion_control_mode(CanonMotionMode, double) override {}
    void set_planner_mode(int, double) override {}
    void set_naivecam_tolerance(double) override {}
    void straight_traverse(int line, const CanonPose &p) override;
    void straight_feed(int line, const CanonPose &p) override;
    void arc_feed(int line, double first_end, double second_end, double first_axis, double second_axis,
                  int rotation, double axis_end, double a, double b, double c, double u, double v,
                  double w) override;
    void turn_probe_on() override {}
    void turn_probe_off() override {}
    void straight_probe(int line, const CanonPose &p, int type) override;
    void rigid_tap(int line, double x, double y, double z, double scale) override;
    void dwell(double seconds) override;
    void nurbs_g5_feed(int line, const std::vector<CanonNurbsPoint> &pts, unsigned order,
                       CanonPlane plane) override;
    void start_speed_feed_synch(int, double, bool) override {}
    void stop_speed_feed_synch() override {}
    void finish() override {}
    void on_reset() override {}
    void set_spindle_mode(int, double) override {}
    void set_spindle_speed(int, double) override {}
    void start_spindle_clockwise(int) override {}
    void start_spindle_counterclockwise(int) override {}
    void stop_spindle_turning(int) override {}
    void orient_spindle(int, double, int) override {}
    void wait_spindle_orient_complete(int, double) override {}
    void mist_on() override {}
    void mist_off() override {}
    void flood_on() override {}
    void flood_off() override {}
    void select_tool(int) override {}
    void change_tool() override;
    void change_tool_number(int) override {}
    void reload_tooldata() override {}
    void set_tool_table_entry(int, const CanonTool &) override {}
    void use_tool_length_offset(const CanonPose &p) override;
    void enable_feed_override() override {}
    void disable_feed_override() override {}
    void enable_speed_override(int) override {}
    void disable_speed_override(int) override {}
    void enable_adaptive_feed() override {}
    void disable_adaptive_feed() override {}
    void enable_feed_hold() override {}
    void disable_feed_hold() override {}
    void set_motion_output_bit(int) override {}
    void clear_motion_output_bit(int) override {}
    void set_aux_output_bit(int) override {}
    void clear_aux_output_bit(int) override {}
    void set_motion_output_value(int, double) override {}
    void set_aux_output_value(int, double) override {}
    int wait_input(int, int, int, double) override { return 0; }
    void comment(const std::string &text) override;
    void message(const std::string &text) override;
    void log(const std::string &) override {}
    void logopen(const std::string &) override {}
    void logappend(const std::string &) override {}
    void logclose() override {}
    void program_stop() override {}
    void optional_program_stop() override {}
    void pallet_shuttle() override {}
    void program_end() override {}
    CanonPose get_external_position() override { return CanonPose(); }
    CanonPose get_external_probe_position() override { return last_; }
    double get_external_probe_tripped_value() override { return 0; }
    double get_external_length_units() override;
    CanonUnits get_external_length_unit_type() override;
    CanonMotionMode get_external_motion_control_mode() override { return CANON_CONTINUOUS; }
    double get_external_motion_control_tolerance() override { return 0; }
    double get_external_motion_control_naivecam_tolerance() override { return 0; }
    int get_external_tool_slot() override { return 0; }
    int get_external_selected_tool_slot() override { return -1; }
    int get_external_digital_input(int, int def) override { return def; }
    double get_external_analog_input(int, double def) override { return def; }
    bool get_external_queue_empty() override { return true; }
    bool get_external_feed_hold_enable() override { return true; }
    bool get_external_adaptive_feed_enable() override { return false; }
    int get_external_toolchanger_fault() override { return 0; }
    int get_external_toolchanger_reason() override { return 0; }

private:
    void next_line();
    void call(const char *method, PyObject *args);
    void call_pose(const char *method, const CanonPose &p);

    PyObject *canon_;              // borrowed: parse() holds the reference
    Interp *interp_ = nullptr;
    int last_line_ = -1;           // sequence number next_line() last reported
    CanonPose last_;               // end of the last move (for NURBS segments)
    CanonPlane plane_ = CANON_PLANE_XY;
    bool failed_ = false;
};

#endif
