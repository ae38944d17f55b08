// record_canon.hh: a Canon for unit tests that prints each call in rs274's text form (LinuxCNC rs274's output).
#ifndef OPENEMC_TESTS_RECORD_CANON_HH
#define OPENEMC_TESTS_RECORD_CANON_HH

#include <cstdio>
#include <string>

#include "emc/rs274ngc/canon.hh"

// Prints one line per call; queries return fixed values.
class RecordCanon : public Canon {
public:
    // print a move with six coordinates
    void move(const char *name, const CanonPose &p)
    {
        std::printf("%s(%.4f, %.4f, %.4f, %.4f, %.4f, %.4f)\n", name, p.x, p.y, p.z, p.a, p.b, p.c);
    }
    // print a call without arguments
    void plain(const char *name) { std::printf("%s()\n", name); }

    void set_g5x_offset(int, const CanonPose &) override { plain("SET_G5X_OFFSET"); }
    void set_g92_offset(const CanonPose &) override { plain("SET_G92_OFFSET"); }
    void set_xy_rotation(double) override { plain("SET_XY_ROTATION"); }
    void use_length_units(CanonUnits) override { plain("USE_LENGTH_UNITS"); }
    void select_plane(CanonPlane) override { plain("SELECT_PLANE"); }
    void set_feed_reference(CanonFeedReference) override { plain("SET_FEED_REFERENCE"); }
    void set_feed_mode(int s, int m) override { std::printf("SET_FEED_MODE(%d, %d)\n", s, m); }
    void set_feed_rate(double r) override { std::printf("SET_FEED_RATE(%.4f)\n", r); }
    // G61/G61.1/G64: the tolerance is printed only in continuous mode, as rs274 does
    void set_motion_control_mode(CanonMotionMode m, double t) override
    {
        if (m == CANON_CONTINUOUS)
            std::printf("SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, %f)\n", t);
        else
            std::printf("SET_MOTION_CONTROL_MODE(%s)\n",
                        m == CANON_EXACT_PATH ? "CANON_EXACT_PATH" : "CANON_EXACT_STOP");
    }
    void set_planner_mode(int, double) override { plain("SET_PLANNER_MODE"); }
    void set_naivecam_tolerance(double t) override { std::printf("SET_NAIVECAM_TOLERANCE(%.4f)\n", t); }

    void straight_traverse(int, const CanonPose &p) override { move("STRAIGHT_TRAVERSE", p); }
    void straight_feed(int, const CanonPose &p) override { move("STRAIGHT_FEED", p); }
    // an arc with its end, center, rotation, axis end and the A B C ends
    void arc_feed(int, double e1, double e2, double c1, double c2, int rot, double ae, double a,
                  double b, double c, double, double, double) override
    {
        std::printf("ARC_FEED(%.4f, %.4f, %.4f, %.4f, %d, %.4f, %.4f, %.4f, %.4f)\n", e1, e2, c1,
                    c2, rot, ae, a, b, c);
    }
    void turn_probe_on() override { plain("TURN_PROBE_ON"); }
    void turn_probe_off() override { plain("TURN_PROBE_OFF"); }
    void straight_probe(int, const CanonPose &p, int) override { move("STRAIGHT_PROBE", p); }
    void rigid_tap(int, double, double, double, double) override { plain("RIGID_TAP"); }
    void dwell(double s) override { std::printf("DWELL(%.4f)\n", s); }
    void nurbs_g5_feed(int, const std::vector<CanonNurbsPoint> &, unsigned, CanonPlane) override
    { plain("NURBS_G5_FEED"); }
    void start_speed_feed_synch(int, double f, bool v) override
    { std::printf("START_SPEED_FEED_SYNC(%f,%d)\n", f, (int)v); }
    void stop_speed_feed_synch() override { plain("STOP_SPEED_FEED_SYNCH"); }
    void finish() override { plain("FINISH"); }
    void on_reset() override { plain("ON_RESET"); }

    void set_spindle_mode(int s, double m) override { std::printf("SET_SPINDLE_MODE(%d %.4f)\n", s, m); }
    void set_spindle_speed(int s, double v) override { std::printf("SET_SPINDLE_SPEED(%d, %.4f)\n", s, v); }
    void start_spindle_clockwise(int s) override { std::printf("START_SPINDLE_CLOCKWISE(%d)\n", s); }
    void start_spindle_counterclockwise(int s) override { std::printf("START_SPINDLE_COUNTERCLOCKWISE(%d)\n", s); }
    void stop_spindle_turning(int s) override { std::printf("STOP_SPINDLE_TURNING(%d)\n", s); }
    void orient_spindle(int, double, int) override { plain("ORIENT_SPINDLE"); }
    void wait_spindle_orient_complete(int, double) override { plain("WAIT_ORIENT_COMPLETE"); }
    void mist_on() override { plain("MIST_ON"); }
    void mist_off() override { plain("MIST_OFF"); }
    void flood_on() override { plain("FLOOD_ON"); }
    void flood_off() override { plain("FLOOD_OFF"); }

    void select_tool(int t) override { std::printf("SELECT_TOOL(%d)\n", t); }
    void change_tool() override { plain("CHANGE_TOOL"); }
    void change_tool_number(int) override { plain("CHANGE_TOOL_NUMBER"); }
    void reload_tooldata() override { plain("RELOAD_TOOLDATA"); }
    void set_tool_table_entry(int, const CanonTool &) override { plain("SET_TOOL_TABLE_ENTRY"); }
    void use_tool_length_offset(const CanonPose &) override { plain("USE_TOOL_LENGTH_OFFSET"); }

    void enable_feed_override() override { plain("ENABLE_FEED_OVERRIDE"); }
    void disable_feed_override() override { plain("DISABLE_FEED_OVERRIDE"); }
    void enable_speed_override(int s) override { std::printf("ENABLE_SPEED_OVERRIDE(%d)\n", s); }
    void disable_speed_override(int s) override { std::printf("DISABLE_SPEED_OVERRIDE(%d)\n", s); }
    void enable_adaptive_feed() override { plain("ENABLE_ADAPTIVE_FEED"); }
    void disable_adaptive_feed() override { plain("DISABLE_ADAPTIVE_FEED"); }
    void enable_feed_hold() override { plain("ENABLE_FEED_HOLD"); }
    void disable_feed_hold() override { plain("DISABLE_FEED_HOLD"); }

    void set_motion_output_bit(int n) override { std::printf("SET_MOTION_OUTPUT_BIT(%d)\n", n); }
    void clear_motion_output_bit(int n) override { std::printf("CLEAR_MOTION_OUTPUT_BIT(%d)\n", n); }
    void set_aux_output_bit(int n) override { std::printf("SET_AUX_OUTPUT_BIT(%d)\n", n); }
    void clear_aux_output_bit(int n) override { std::printf("CLEAR_AUX_OUTPUT_BIT(%d)\n", n); }
    void set_motion_output_value(int, double) override { plain("SET_MOTION_OUTPUT_VALUE"); }
    void set_aux_output_value(int, double) override { plain("SET_AUX_OUTPUT_VALUE"); }
    int wait_input(int, int, int, double) override { return 0; }

    void comment(const std::string &t) override { std::printf("COMMENT(\"%s\")\n", t.c_str()); }
    void message(const std::string &t) override { std::printf("MESSAGE(\"%s\")\n", t.c_str()); }
    void log(const std::string &) override { plain("LOG"); }
    void logopen(const std::string &) override { plain("LOGOPEN"); }
    void logappend(const std::string &) override { plain("LOGAPPEND"); }
    void logclose() override { plain("LOGCLOSE"); }
    void program_stop() override { plain("PROGRAM_STOP"); }
    void optional_program_stop() override { plain("OPTIONAL_PROGRAM_STOP"); }
    void pallet_shuttle() override { plain("PALLET_SHUTTLE"); }
    void program_end() override { plain("PROGRAM_END"); }

    CanonPose get_external_position() override { return {}; }
    CanonPose get_external_probe_position() override { return {}; }
    double get_external_probe_tripped_value() override { return 0; }
    double get_external_length_units() override { return 1; }
    CanonUnits get_external_length_unit_type() override { return CANON_UNITS_MM; }
    CanonMotionMode get_external_motion_control_mode() override { return CANON_CONTINUOUS; }
    double get_external_motion_control_tolerance() override { return 0; }
    double get_external_motion_control_naivecam_tolerance() override { return 0; }
    int get_external_tool_slot() override { return 0; }
    int get_external_selected_tool_slot() override { return 0; }
    int get_external_digital_input(int, int d) override { return d; }
    double get_external_analog_input(int, double d) override { return d; }
    bool get_external_queue_empty() override { return true; }
    bool get_external_feed_hold_enable() override { return true; }
    bool get_external_adaptive_feed_enable() override { return false; }
    int get_external_toolchanger_fault() override { return 0; }
    int get_external_toolchanger_reason() override { return 0; }
};

#endif
