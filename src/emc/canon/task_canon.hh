// task_canon.hh: the canon calls of the interpreter turned into NML messages on the interp list (LinuxCNC's emccanon).
#ifndef TASK_CANON_HH
#define TASK_CANON_HH

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "canon.hh"
#include "canon_limits.h"
#include "emc_nml.hh"
#include "interp_list.hh"

// The machine as canon sees it: static configuration, machine units.
struct CanonConfig {
    double linear_units = 1.0;      // machine units per mm (inch machine: 1/25.4)
    double angular_units = 1.0;     // machine units per degree
    int axis_mask = 7;              // X=1 Y=2 Z=4 A=8 ... W=256
    int spindles = 1;
    canon_axis_limits_t limits = {};  // [AXIS_L] MAX_VELOCITY / MAX_ACCELERATION / MAX_JERK
    int tool_change_axes = 0;         // M6 first moves these (3, 6 or 9; 0 = no move) ...
    double tool_change_position[9] = {};  // ... to here: XYZABCUVW machine coordinates
};

// Live machine state the canon queries answer from (task reads it from motion and io status).
class CanonMachine {
public:
    virtual ~CanonMachine() = default;
    virtual EmcPose position() = 0;          // commanded pose, machine coordinates
    virtual EmcPose probed_position() = 0;   // where the last probe tripped
    virtual double probe_tripped_value() = 0;
    virtual int digital_input(int index) = 0;
    virtual double analog_input(int index) = 0;
    virtual int tool_slot() = 0;             // tool-data index of the loaded tool
    virtual int selected_tool_slot() = 0;    // tool-data index of the prepared tool, -1 none
    virtual int tool_index(int toolno) = 0;  // tool-data index of tool toolno, -1 none
    virtual bool queue_empty() = 0;
    virtual int toolchanger_fault() = 0;
    virtual int toolchanger_reason() = 0;
};

// What one interpreter block asked for that needs real machine state afterwards.
struct CanonBlockNeeds {
    bool probe = false;        // a probe ran: #5061-#5070 after it finished
    bool wait_input = false;   // M66: #5399 after it finished
    int wait_index = 0;
    bool wait_digital = true;
    bool tool_data = false;    // the tool table changed (G10 L1/L10/L11, M61, M6)
};

class TaskCanon : public Canon {
public:
    TaskCanon(const CanonConfig &cfg, CanonMachine &machine, InterpList &list);
    ~TaskCanon() override;

    // Supplies the state tag carried by each move (the interpreter's modal state).
    void set_tagger(std::function<void(state_tag_t &)> fn) { tagger_ = std::move(fn); }
    // Where the next move starts (machine coordinates): after a synch or an abort.
    void set_position(const EmcPose &p) { end_ = p; chain_.clear(); }
    // Flush the held naive-CAM chain (before the list is issued or at a block end).
    void flush();
    // What the blocks since the last call needed; clears it.
    CanonBlockNeeds take_needs();
    // Canon state read by status (machine units).
    const EmcPose &g5x_offset() const { return g5x_; }
    int g5x_index() const { return g5x_index_; }
    const EmcPose &g92_offset() const { return g92_; }
    double rotation_xy() const { return rotation_; }
    const EmcPose &tool_offset() const { return tool_; }
    CanonUnits program_units() const { return units_; }
    // Program pose -> machine pose and back (used by the queries and by tests).
    EmcPose to_machine(const CanonPose &p) const;
    CanonPose to_program(const EmcPose &m) const;
    // Block delete / optional stop switches as the interpreter sees them.
    void set_switches(bool block_delete, bool optional_stop) { block_delete_ = block_delete; optional_stop_ = optional_stop; }

    // ---- Canon ----
    void init_canon() override;
    void set_g5x_offset(int origin, const CanonPose &p) override;
    void set_g92_offset(const CanonPose &p) override;
    void set_xy_rotation(double deg) override;
    void use_length_units(CanonUnits u) override;
    void select_plane(CanonPlane p) override { plane_ = p; }
    void set_feed_reference(CanonFeedReference) override {}
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
    void turn_probe_off() override {}
    void straight_probe(int line, const CanonPose &p, int type) override;
    void rigid_tap(int line, double x, double y, double z, double scale) override;
    void dwell(double seconds) override;
    void nurbs_g5_feed(int line, const std::vector<CanonNurbsPoint> &pts, unsigned order,
                       CanonPlane plane) override;
    void start_speed_feed_synch(int spindle, double feed_per_rev, bool velocity_mode) override;
    void stop_speed_feed_synch() override;
    void finish() override { flush(); }
    void on_reset() override { flush(); }
    void set_spindle_mode(int spindle, double css_max) override;
    void set_spindle_speed(int spindle, double speed) override;
    void start_spindle_clockwise(int spindle) override { spindle_on(spindle, 1); }
    void start_spindle_counterclockwise(int spindle) override { spindle_on(spindle, -1); }
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
    void enable_feed_override() override { override_enable(EMC_TRAJ_SET_FO_ENABLE_TYPE, 0, true); }
    void disable_feed_override() override { override_enable(EMC_TRAJ_SET_FO_ENABLE_TYPE, 0, false); }
    void enable_speed_override(int sp) override { override_enable(EMC_TRAJ_SET_SO_ENABLE_TYPE, sp, true); }
    void disable_speed_override(int sp) override { override_enable(EMC_TRAJ_SET_SO_ENABLE_TYPE, sp, false); }
    void enable_adaptive_feed() override;
    void disable_adaptive_feed() override;
    void enable_feed_hold() override { override_enable(EMC_TRAJ_SET_FH_ENABLE_TYPE, 0, true); }
    void disable_feed_hold() override { override_enable(EMC_TRAJ_SET_FH_ENABLE_TYPE, 0, false); }
    void set_motion_output_bit(int n) override { digital_out(n, true, false); }
    void clear_motion_output_bit(int n) override { digital_out(n, false, false); }
    void set_aux_output_bit(int n) override { digital_out(n, true, true); }
    void clear_aux_output_bit(int n) override { digital_out(n, false, true); }
    void set_motion_output_value(int n, double v) override { analog_out(n, v, false); }
    void set_aux_output_value(int n, double v) override { analog_out(n, v, true); }
    int wait_input(int index, int input_type, int wait_type, double timeout) override;
    void lock_rotary(int line, int joint) override;
    void unlock_rotary(int line, int joint) override;
    void comment(const std::string &) override {}
    void message(const std::string &text) override;
    void log(const std::string &text) override;
    void logopen(const std::string &name) override;
    void logappend(const std::string &name) override;
    void logclose() override;
    void program_stop() override;
    void optional_program_stop() override;
    void pallet_shuttle() override {}
    void program_end() override;
    void set_block_delete(bool on) override { block_delete_ = on; }
    void set_optional_program_stop(bool on) override { optional_stop_ = on; }
    CanonPose get_external_position() override;
    CanonPose get_external_probe_position() override;
    double get_external_probe_tripped_value() override { return machine_.probe_tripped_value(); }
    double get_external_length_units() override { return cfg_.linear_units; }
    CanonUnits get_external_length_unit_type() override;
    CanonMotionMode get_external_motion_control_mode() override { return motion_mode_; }
    double get_external_motion_control_tolerance() override { return from_mu(tolerance_); }
    double get_external_motion_control_naivecam_tolerance() override { return from_mu(naivecam_tol_); }
    int get_external_tool_slot() override { return machine_.tool_slot(); }
    int get_external_selected_tool_slot() override { return machine_.selected_tool_slot(); }
    int get_external_digital_input(int index, int def) override;
    double get_external_analog_input(int index, double def) override;
    bool get_external_queue_empty() override { return machine_.queue_empty(); }
    bool get_external_feed_hold_enable() override { return feed_hold_; }
    bool get_external_adaptive_feed_enable() override { return adaptive_; }
    int get_external_toolchanger_fault() override { return machine_.toolchanger_fault(); }
    int get_external_toolchanger_reason() override { return machine_.toolchanger_reason(); }

private:
    double mm_per_unit() const;
    double unit_factor() const;
    double to_mu(double program_len) const { return program_len * unit_factor(); }
    double from_mu(double mu) const { return mu / unit_factor(); }
    double ang_to_mu(double deg) const { return deg * cfg_.angular_units; }
    EmcPose offsets_pose(const CanonPose &p) const;
    state_tag_t tag() const;
    void queue_line(int line, const EmcPose &end, int type, double feed_vel, const state_tag_t *t = nullptr);
    void feed_chain(int line, const EmcPose &end);
    bool chain_accepts(const EmcPose &end) const;
    double move_feed_vel() const;
    void spindle_on(int spindle, int dir);
    void emit_spindle_speed(int spindle);
    void override_enable(NMLTYPE type, int spindle, bool on);
    void digital_out(int n, bool on, bool now);
    void analog_out(int n, double v, bool now);
    void emit_sync(int spindle, double fpr_mu, bool velocity_mode);
    void arc_geometry(const EmcPose &end, double c1, double c2, int rotation,
                      EMC_TRAJ_CIRCULAR_MOVE &m, int &p1, int &p2, double &arc_len) const;
    void arc_as_lines(int line, const EmcPose &end, const EmcPose &center, int rotation, int p1, int p2);

    CanonConfig cfg_;
    CanonMachine &machine_;
    InterpList &list_;
    std::function<void(state_tag_t &)> tagger_;
    CanonUnits units_ = CANON_UNITS_MM;
    CanonPlane plane_ = CANON_PLANE_XY;
    EmcPose g5x_ = {}, g92_ = {}, tool_ = {};
    int g5x_index_ = 1;
    double rotation_ = 0;             // degrees
    EmcPose end_ = {};                // end of the last queued move, machine coordinates
    double feed_ = 0;                 // mu/s (per minute mode) or mu/rev (per rev mode)
    double feed_prog_ = 0;            // F as programmed (units or degrees per minute)
    int feed_mode_ = 0;               // 0 per minute / inverse time, 1 per revolution
    int feed_spindle_ = 0;
    CanonMotionMode motion_mode_ = CANON_CONTINUOUS;
    double tolerance_ = 0, naivecam_tol_ = 0;   // mu
    int planner_type_ = -1;
    double peak_scale_ = 1.0;
    double speed_[EMCMOT_MAX_SPINDLES] = {};    // rpm, or surface speed in G96
    double css_max_[EMCMOT_MAX_SPINDLES] = {};  // G96 D (0 = G97)
    int dir_[EMCMOT_MAX_SPINDLES] = {};
    bool feed_hold_ = true, adaptive_ = false;
    bool block_delete_ = false, optional_stop_ = false;
    bool synced_ = false;             // position-synced motion (G33) in force
    // held naive-CAM chain: the queued line's start and the points merged into it
    std::vector<EmcPose> chain_;
    EmcPose chain_start_ = {};
    EMC_TRAJ_LINEAR_MOVE chain_move_;
    int chain_line_ = 0;
    state_tag_t chain_tag_ = {};      // the tag of the last point merged into the chain
    CanonBlockNeeds needs_;
    FILE *log_ = nullptr;
};

#endif
