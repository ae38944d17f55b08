// sim_motion.hh: motion as openemc-estimate simulates it: EMCMOT commands into the planner library, servo cycles in simulated time.
#ifndef SIM_MOTION_HH
#define SIM_MOTION_HH

#include <string>
#include <vector>

#include "kins_coords.h"
#include "machine_config.hh"
#include "motion_cmd.h"
#include "tp_planner.h"

// One servo cycle as the estimator records it.
struct SimSample {
    EmcPose pos;                // commanded world position
    double vel;                 // path speed (motion.current-vel)
    double requested_vel;       // programmed speed capped by the machine (motion.requested-vel)
    int line;                   // executing move's id (source line)
    int motion_type;            // TP_MOTION_*, 0 idle
};

// Motion's planner side without HAL: the limit checks of a queued move, the settings the planner
// takes from motion, an ideal spindle (at the commanded speed at once, index pulse once a turn)
// and identity kinematics for the joint limits.  Feed and rapid override stay at 100 %.
class SimMotion {
public:
    // cfg: the machine; coords: the identity kinematics' joint-to-axis map.
    SimMotion(const MachineConfig &cfg, const kins_coords_t &coords);
    ~SimMotion();
    SimMotion(const SimMotion &) = delete;
    SimMotion &operator=(const SimMotion &) = delete;

    // Apply one command as motion would; false with *error set when motion would refuse it.
    bool apply(const emcmot_command_t &c, std::string *error);
    // One trajectory cycle; the sample of it.
    SimSample cycle();
    // Queue empty and at rest.
    bool done() const { return tp_planner_is_done(tp_) != 0; }
    // No room for another move.
    bool queue_full() const { return tp_planner_queue_full(tp_) != 0; }
    // Where the planner stands.
    EmcPose position() const;
    // Servo and trajectory period, seconds (trajectory 0: the servo period).
    void set_periods(double servo_s, double traj_s);
    // Start the planner at pose p (the homed position).
    void set_position(const EmcPose &p);
    // Trajectory period, seconds, and servo cycles per trajectory cycle.
    double period() const { return limits_.cycle_time; }
    int servo_per_traj() const { return interp_rate_; }
    // Cycles the planner found no safe continuation in (0 on a correct run).
    unsigned long emergencies() const { return tp_planner_emergencies(tp_); }

private:
    using Handler = bool (SimMotion::*)(const emcmot_command_t &, std::string *);
    struct Entry {
        int code;
        Handler fn;
    };
    static const Entry table_[];

    void limits_changed();
    bool check_move(const emcmot_command_t &c, const char *word, std::string *error) const;
    bool queue_move(const emcmot_command_t &c, std::string *error);
    void spindle_step(const tp_cycle_out_t &out);

    bool cmd_move(const emcmot_command_t &c, std::string *error);
    bool cmd_traj(const emcmot_command_t &c, std::string *error);
    bool cmd_axis(const emcmot_command_t &c, std::string *error);
    bool cmd_joint_limits(const emcmot_command_t &c, std::string *error);
    bool cmd_term_cond(const emcmot_command_t &c, std::string *error);
    bool cmd_planner_type(const emcmot_command_t &c, std::string *error);
    bool cmd_enables(const emcmot_command_t &c, std::string *error);
    bool cmd_spindle(const emcmot_command_t &c, std::string *error);
    bool cmd_sync_io(const emcmot_command_t &c, std::string *error);
    bool cmd_ignore(const emcmot_command_t &c, std::string *error);

    tp_planner_t *tp_ = nullptr;
    tp_limits_t limits_ = {};
    kins_coords_t coords_;
    int interp_rate_ = 1;
    int num_joints_ = 3;
    std::vector<double> joint_min_, joint_max_;
    double axis_min_[EMCMOT_MAX_AXIS], axis_max_[EMCMOT_MAX_AXIS];
    bool fs_enabled_ = true, fh_enabled_ = true, af_enabled_ = false;
    double spindle_sync_ = 0.0;
    bool atspeed_next_feed_ = false;   // a spindle change asked the next feed move to wait for at-speed
    double spindle_rpm_[TP_MAX_SPINDLES] = {};
    double css_factor_[TP_MAX_SPINDLES] = {};
    double css_xoffset_[TP_MAX_SPINDLES] = {};
    int planner_type_pending_ = -1;
    EmcPose queued_end_ = {};
    tp_cycle_in_t in_ = {};
};

#endif
