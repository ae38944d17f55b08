// comp_filter.hh: a Canon that forwards calls to the real canon, deferring some behind held compensated moves.
#ifndef OPENEMC_RS274NGC_COMP_FILTER_HH
#define OPENEMC_RS274NGC_COMP_FILTER_HH

#include "comp_queue.hh"

namespace cutcomp {

// Pass-through Canon; motion calls are left to the compensation engine that derives from it.
class CompFilter : public Canon {
public:
    // forward to `out`
    explicit CompFilter(Canon &out) : out_(out) {}

    // setup calls print at once; feed mode and rate wait behind held moves

    void set_g5x_offset(int origin, const CanonPose &p) override { out_.set_g5x_offset(origin, p); }
    void set_g92_offset(const CanonPose &p) override { out_.set_g92_offset(p); }
    void set_xy_rotation(double deg) override { out_.set_xy_rotation(deg); }
    void use_length_units(CanonUnits u) override { out_.use_length_units(u); }
    void select_plane(CanonPlane p) override { out_.select_plane(p); }
    void set_feed_reference(CanonFeedReference r) override { out_.set_feed_reference(r); }
    void set_feed_mode(int s, int m) override { later([=](Canon &c) { c.set_feed_mode(s, m); }); }
    void set_feed_rate(double r) override { later([=](Canon &c) { c.set_feed_rate(r); }); }
    void set_motion_control_mode(CanonMotionMode m, double t) override { out_.set_motion_control_mode(m, t); }
    void set_planner_mode(int type, double peak) override { out_.set_planner_mode(type, peak); }
    void set_naivecam_tolerance(double t) override { out_.set_naivecam_tolerance(t); }
    void set_traverse_rate(double r) override { out_.set_traverse_rate(r); }

    // motion that is not compensated flushes first; dwell waits behind held moves
    void turn_probe_on() override { flush_all(); out_.turn_probe_on(); }
    void turn_probe_off() override { flush_all(); out_.turn_probe_off(); }
    void straight_probe(int line, const CanonPose &p, int type) override { flush_all(); out_.straight_probe(line, p, type); }
    void rigid_tap(int line, double x, double y, double z, double k) override { flush_all(); out_.rigid_tap(line, x, y, z, k); }
    void dwell(double s) override { later([=](Canon &c) { c.dwell(s); }); }
    void nurbs_g5_feed(int line, const std::vector<CanonNurbsPoint> &pts, unsigned order, CanonPlane plane) override
    { flush_all(); out_.nurbs_g5_feed(line, pts, order, plane); }
    void start_speed_feed_synch(int s, double f, bool v) override { flush_all(); out_.start_speed_feed_synch(s, f, v); }
    void stop_speed_feed_synch() override { flush_all(); out_.stop_speed_feed_synch(); }
    void finish() override { flush_all(); out_.finish(); }
    void on_reset() override { out_.on_reset(); }

    // spindle and coolant calls wait behind held moves
    void set_spindle_mode(int s, double m) override { later([=](Canon &c) { c.set_spindle_mode(s, m); }); }
    void set_spindle_speed(int s, double v) override { later([=](Canon &c) { c.set_spindle_speed(s, v); }); }
    void start_spindle_clockwise(int s) override { later([=](Canon &c) { c.start_spindle_clockwise(s); }); }
    void start_spindle_counterclockwise(int s) override { later([=](Canon &c) { c.start_spindle_counterclockwise(s); }); }
    void stop_spindle_turning(int s) override { later([=](Canon &c) { c.stop_spindle_turning(s); }); }
    void orient_spindle(int s, double a, int m) override { later([=](Canon &c) { c.orient_spindle(s, a, m); }); }
    void wait_spindle_orient_complete(int s, double t) override { later([=](Canon &c) { c.wait_spindle_orient_complete(s, t); }); }
    void mist_on() override { later([](Canon &c) { c.mist_on(); }); }
    void mist_off() override { later([](Canon &c) { c.mist_off(); }); }
    void flood_on() override { later([](Canon &c) { c.flood_on(); }); }
    void flood_off() override { later([](Canon &c) { c.flood_off(); }); }

    // tool, override and I/O calls print at once
    void select_tool(int t) override { out_.select_tool(t); }
    void change_tool() override { out_.change_tool(); }
    void change_tool_number(int i) override { out_.change_tool_number(i); }
    void reload_tooldata() override { out_.reload_tooldata(); }
    void set_tool_table_entry(int i, const CanonTool &t) override { out_.set_tool_table_entry(i, t); }
    void use_tool_length_offset(const CanonPose &p) override { out_.use_tool_length_offset(p); }

    void enable_feed_override() override { out_.enable_feed_override(); }
    void disable_feed_override() override { out_.disable_feed_override(); }
    void enable_speed_override(int s) override { out_.enable_speed_override(s); }
    void disable_speed_override(int s) override { out_.disable_speed_override(s); }
    void enable_adaptive_feed() override { out_.enable_adaptive_feed(); }
    void disable_adaptive_feed() override { out_.disable_adaptive_feed(); }
    void enable_feed_hold() override { out_.enable_feed_hold(); }
    void disable_feed_hold() override { out_.disable_feed_hold(); }

    void set_motion_output_bit(int n) override { out_.set_motion_output_bit(n); }
    void clear_motion_output_bit(int n) override { out_.clear_motion_output_bit(n); }
    void set_aux_output_bit(int n) override { out_.set_aux_output_bit(n); }
    void clear_aux_output_bit(int n) override { out_.clear_aux_output_bit(n); }
    void set_motion_output_value(int n, double v) override { out_.set_motion_output_value(n, v); }
    void set_aux_output_value(int n, double v) override { out_.set_aux_output_value(n, v); }
    int wait_input(int i, int t, int w, double to) override { return out_.wait_input(i, t, w, to); }
    void lock_rotary(int l, int j) override { out_.lock_rotary(l, j); }
    void unlock_rotary(int l, int j) override { out_.unlock_rotary(l, j); }

    // comments wait; messages, logs and program stops print at once; program end flushes
    void comment(const std::string &t) override { later([=](Canon &c) { c.comment(t); }); }
    void message(const std::string &t) override { out_.message(t); }
    void log(const std::string &t) override { out_.log(t); }
    void logopen(const std::string &n) override { out_.logopen(n); }
    void logappend(const std::string &n) override { out_.logappend(n); }
    void logclose() override { out_.logclose(); }
    void program_stop() override { out_.program_stop(); }
    void optional_program_stop() override { out_.optional_program_stop(); }
    void pallet_shuttle() override { out_.pallet_shuttle(); }
    void program_end() override { flush_all(); out_.program_end(); }
    void set_block_delete(bool b) override { out_.set_block_delete(b); }
    void set_optional_program_stop(bool b) override { out_.set_optional_program_stop(b); }
    void update_tag(int t) override { out_.update_tag(t); }

    // queries go straight to the real canon
    CanonPose get_external_position() override { return out_.get_external_position(); }
    CanonPose get_external_probe_position() override { return out_.get_external_probe_position(); }
    double get_external_probe_tripped_value() override { return out_.get_external_probe_tripped_value(); }
    double get_external_length_units() override { return out_.get_external_length_units(); }
    CanonUnits get_external_length_unit_type() override { return out_.get_external_length_unit_type(); }
    CanonMotionMode get_external_motion_control_mode() override { return out_.get_external_motion_control_mode(); }
    double get_external_motion_control_tolerance() override { return out_.get_external_motion_control_tolerance(); }
    double get_external_motion_control_naivecam_tolerance() override { return out_.get_external_motion_control_naivecam_tolerance(); }
    int get_external_tool_slot() override { return out_.get_external_tool_slot(); }
    int get_external_selected_tool_slot() override { return out_.get_external_selected_tool_slot(); }
    int get_external_digital_input(int i, int d) override { return out_.get_external_digital_input(i, d); }
    double get_external_analog_input(int i, double d) override { return out_.get_external_analog_input(i, d); }
    bool get_external_queue_empty() override { return out_.get_external_queue_empty(); }
    bool get_external_feed_hold_enable() override { return out_.get_external_feed_hold_enable(); }
    bool get_external_adaptive_feed_enable() override { return out_.get_external_adaptive_feed_enable(); }
    int get_external_toolchanger_fault() override { return out_.get_external_toolchanger_fault(); }
    int get_external_toolchanger_reason() override { return out_.get_external_toolchanger_reason(); }

protected:
    // a call that waits behind held moves, or goes out at once when nothing is held
    void later(std::function<void(Canon &)> call);
    // emit every held move and deferred call
    virtual void flush_all() = 0;

    Canon &out_;
    CompQueue queue_;
};

}  // namespace cutcomp

#endif
