// sim_motion.cc: the estimator's motion: command handlers (a table), move checks, planner cycles and an ideal spindle.
#include "sim_motion.hh"

#include <cmath>
#include <cstring>

namespace {

// Segments the planner holds, as motmod's queue.
const int QUEUE_SIZE = 2000;
const char AXIS_LETTERS[] = "XYZABCUVW";

// Value of axis a (0..8) of a pose.
double pose_get(const EmcPose &p, int a) { return kins_pose_get(&p, a); }

}  // namespace

// Planner, limits and the homed start from the machine configuration (the start-up stream the
// translator sends sets the rest).
SimMotion::SimMotion(const MachineConfig &cfg, const kins_coords_t &coords) : coords_(coords)
{
    tp_ = tp_planner_create(QUEUE_SIZE);
    num_joints_ = cfg.joints;
    joint_min_.assign(EMCMOT_MAX_JOINTS, -1e99);
    joint_max_.assign(EMCMOT_MAX_JOINTS, 1e99);
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        axis_min_[a] = -1e99;
        axis_max_[a] = 1e99;
    }
    limits_.cycle_time = 0.001;
    limits_.max_feed_override = 1.0;
    limits_.scurve_peak_scale = 1.0;
    in_.feed_scale = in_.rapid_scale = in_.adaptive_feed = 1.0;
    in_.num_spindles = cfg.spindles < TP_MAX_SPINDLES ? cfg.spindles : TP_MAX_SPINDLES;
    for (int s = 0; s < TP_MAX_SPINDLES; s++) in_.spindle[s].at_speed = 1;
}

SimMotion::~SimMotion() { tp_planner_destroy(tp_); }

// Trajectory and servo period, seconds (motmod's traj_period_nsec: 0 = the servo period).
void SimMotion::set_periods(double servo_s, double traj_s)
{
    if (!(traj_s > 0.0)) traj_s = servo_s;
    limits_.cycle_time = traj_s;
    interp_rate_ = (int)std::lround(traj_s / servo_s);
    if (interp_rate_ < 1) interp_rate_ = 1;
    limits_changed();
}

// Hand the limits to the planner (motion's mot_tp_limits_changed).
void SimMotion::limits_changed() { tp_planner_set_limits(tp_, &limits_); }

EmcPose SimMotion::position() const
{
    EmcPose p = {};
    tp_planner_get_pos(tp_, &p);
    return p;
}

void SimMotion::set_position(const EmcPose &p)
{
    tp_planner_set_pos(tp_, &p);
    queued_end_ = p;
}

// The command table: which handler takes which EMCMOT command.
const SimMotion::Entry SimMotion::table_[] = {
    {EMCMOT_SET_LINE, &SimMotion::cmd_move},
    {EMCMOT_SET_CIRCLE, &SimMotion::cmd_move},
    {EMCMOT_PROBE, &SimMotion::cmd_move},
    {EMCMOT_RIGID_TAP, &SimMotion::cmd_move},
    {EMCMOT_SET_VEL, &SimMotion::cmd_traj},
    {EMCMOT_SET_VEL_LIMIT, &SimMotion::cmd_traj},
    {EMCMOT_SET_ACC, &SimMotion::cmd_traj},
    {EMCMOT_SET_JERK, &SimMotion::cmd_traj},
    {EMCMOT_SET_MAX_FEED_OVERRIDE, &SimMotion::cmd_traj},
    {EMCMOT_SET_SCURVE_PEAK_SCALE, &SimMotion::cmd_traj},
    {EMCMOT_SETUP_ARC_BLENDS, &SimMotion::cmd_traj},
    {EMCMOT_SET_AXIS_POSITION_LIMITS, &SimMotion::cmd_axis},
    {EMCMOT_SET_AXIS_VEL_LIMIT, &SimMotion::cmd_axis},
    {EMCMOT_SET_AXIS_ACC_LIMIT, &SimMotion::cmd_axis},
    {EMCMOT_SET_AXIS_JERK_LIMIT, &SimMotion::cmd_axis},
    {EMCMOT_SET_JOINT_POSITION_LIMITS, &SimMotion::cmd_joint_limits},
    {EMCMOT_SET_TERM_COND, &SimMotion::cmd_term_cond},
    {EMCMOT_SET_PLANNER_TYPE, &SimMotion::cmd_planner_type},
    {EMCMOT_FS_ENABLE, &SimMotion::cmd_enables},
    {EMCMOT_FH_ENABLE, &SimMotion::cmd_enables},
    {EMCMOT_AF_ENABLE, &SimMotion::cmd_enables},
    {EMCMOT_SET_SPINDLESYNC, &SimMotion::cmd_spindle},
    {EMCMOT_SPINDLE_ON, &SimMotion::cmd_spindle},
    {EMCMOT_SPINDLE_OFF, &SimMotion::cmd_spindle},
    {EMCMOT_SET_DOUT, &SimMotion::cmd_sync_io},
    {EMCMOT_SET_AOUT, &SimMotion::cmd_sync_io},
};

bool SimMotion::apply(const emcmot_command_t &c, std::string *error)
{
    for (const Entry &e : table_)
        if (e.code == c.command) return (this->*e.fn)(c, error);
    return cmd_ignore(c, error);
}

// Commands that change nothing the planner or the estimate sees (homing, jogs, joints' servo
// settings, spindle parameters, mode changes, immediate outputs' hardware side).
bool SimMotion::cmd_ignore(const emcmot_command_t &, std::string *) { return true; }

// [TRAJ] settings and overrides' ceilings.
bool SimMotion::cmd_traj(const emcmot_command_t &c, std::string *error)
{
    double v = c.command == EMCMOT_SET_ACC ? c.acc : c.command == EMCMOT_SET_JERK ? c.jerk
             : (c.command == EMCMOT_SET_MAX_FEED_OVERRIDE || c.command == EMCMOT_SET_SCURVE_PEAK_SCALE) ? c.scale
             : c.vel;
    if (v < 0.0 || (c.command == EMCMOT_SET_VEL && c.ini_maxvel < 0.0)) {
        *error = std::string(emcmot_command_name(c.command)) + ": negative value";
        return false;
    }
    switch (c.command) {
    case EMCMOT_SET_VEL: limits_.vmax = c.vel; limits_.ini_maxvel = c.ini_maxvel; break;
    case EMCMOT_SET_VEL_LIMIT: limits_.vlimit = c.vel; break;
    case EMCMOT_SET_ACC: limits_.amax = c.acc; break;
    case EMCMOT_SET_JERK: limits_.jmax = c.jerk; break;
    case EMCMOT_SET_MAX_FEED_OVERRIDE: limits_.max_feed_override = c.scale; break;
    case EMCMOT_SET_SCURVE_PEAK_SCALE: limits_.scurve_peak_scale = std::fmin(1.0, std::fmax(0.1, c.scale)); break;
    default:
        limits_.arc_blend_enable = c.arc_blend_enable;
        limits_.arc_blend_fallback_enable = c.arc_blend_fallback_enable;
        limits_.arc_blend_optimization_depth = c.arc_blend_optimization_depth;
        limits_.arc_blend_gap_cycles = c.arc_blend_gap_cycles;
        limits_.arc_blend_ramp_freq = c.arc_blend_ramp_freq;
        limits_.arc_blend_tangent_kink_ratio = c.arc_blend_tangent_kink_ratio;
        break;
    }
    limits_changed();
    return true;
}

// Per-axis position, velocity, acceleration and jerk limits.
bool SimMotion::cmd_axis(const emcmot_command_t &c, std::string *error)
{
    int a = c.axis;
    if (a < 0 || a >= EMCMOT_MAX_AXIS) {
        *error = std::string(emcmot_command_name(c.command)) + ": bad axis " + std::to_string(a);
        return false;
    }
    switch (c.command) {
    case EMCMOT_SET_AXIS_POSITION_LIMITS: axis_min_[a] = c.min_limit; axis_max_[a] = c.max_limit; return true;
    case EMCMOT_SET_AXIS_VEL_LIMIT: limits_.axis_vel[a] = c.vel; break;
    case EMCMOT_SET_AXIS_ACC_LIMIT: limits_.axis_acc[a] = c.acc; break;
    default: limits_.axis_jerk[a] = c.jerk; break;
    }
    limits_changed();
    return true;
}

bool SimMotion::cmd_joint_limits(const emcmot_command_t &c, std::string *)
{
    if (c.joint >= 0 && c.joint < EMCMOT_MAX_JOINTS) {
        joint_min_[c.joint] = c.min_limit;
        joint_max_[c.joint] = c.max_limit;
    }
    return true;
}

bool SimMotion::cmd_term_cond(const emcmot_command_t &c, std::string *error)
{
    if (tp_planner_set_term_cond(tp_, (tp_term_cond_t)c.term_cond, c.tolerance) != TP_OK) {
        *error = "SET_TERM_COND: bad condition " + std::to_string(c.term_cond);
        return false;
    }
    return true;
}

// PLANNER_TYPE / G64 R: deferred while motion is queued, as motion does.
bool SimMotion::cmd_planner_type(const emcmot_command_t &c, std::string *error)
{
    if (!done()) {
        planner_type_pending_ = c.planner_type;
        return true;
    }
    tp_result_t r = tp_planner_set_type(tp_, (tp_planner_type_t)c.planner_type);
    if (r == TP_NO_JERK_LIMIT) {
        *error = "S-curve planner refused: no usable jerk limit - set [TRAJ]MAX_LINEAR_JERK and "
                 "per-axis [AXIS_*]MAX_JERK";
        return false;
    }
    planner_type_pending_ = -1;
    return true;
}

bool SimMotion::cmd_enables(const emcmot_command_t &c, std::string *)
{
    bool on = c.enable != 0;
    if (c.command == EMCMOT_FS_ENABLE) fs_enabled_ = on;
    else if (c.command == EMCMOT_FH_ENABLE) fh_enabled_ = on;
    else af_enabled_ = on;
    return true;
}

// Spindle on/off (speed, constant surface speed) and the sync of the moves that follow.
bool SimMotion::cmd_spindle(const emcmot_command_t &c, std::string *error)
{
    if (c.command == EMCMOT_SET_SPINDLESYNC) {
        spindle_sync_ = c.spindle_sync;
        return true;
    }
    int first = c.spindle < 0 ? 0 : c.spindle, last = c.spindle < 0 ? in_.num_spindles - 1 : c.spindle;
    if (first >= in_.num_spindles) {
        *error = "Attempt to use non-existent spindle " + std::to_string(c.spindle);
        return false;
    }
    for (int s = first; s <= last; s++) {
        bool on = c.command == EMCMOT_SPINDLE_ON;
        spindle_rpm_[s] = on ? c.speed : 0.0;
        css_factor_[s] = on ? c.css_factor : 0.0;
        css_xoffset_[s] = c.css_xoffset;
    }
    if (c.wait_for_at_speed) atspeed_next_feed_ = true;    // as motion: the next feed move waits
    return true;
}

// M62-M68: synced outputs ride with the next move; immediate ones change nothing here.
bool SimMotion::cmd_sync_io(const emcmot_command_t &c, std::string *)
{
    if (c.now) return true;
    if (c.command == EMCMOT_SET_DOUT) tp_planner_set_dout(tp_, c.io_index, c.dout_start != 0, c.dout_end != 0);
    else tp_planner_set_aout(tp_, c.io_index, c.aout_start, c.aout_end);
    return true;
}

// Axis limits of the end point and joint limits through the identity kinematics (motion's
// messages); false with *error when the move would leave them.
bool SimMotion::check_move(const emcmot_command_t &c, const char *word, std::string *error) const
{
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        double v = pose_get(c.pos, a);
        if (v > axis_max_[a] || v < axis_min_[a]) {
            *error = std::string(word) + " move on line " + std::to_string(c.id) + " would exceed " +
                     AXIS_LETTERS[a] + "'s " + (v > axis_max_[a] ? "positive" : "negative") + " limit";
            return false;
        }
    }
    double joints[KINS_MAX_JOINTS] = {0};
    kins_identity_inverse(&coords_, &c.pos, joints);
    for (int j = 0; j < num_joints_ && j < coords_.joint_count; j++) {
        if (joints[j] > joint_max_[j] || joints[j] < joint_min_[j]) {
            char buf[160];
            snprintf(buf, sizeof buf, "%s move on line %d would exceed joint %d's %s limit", word, c.id, j,
                     joints[j] > joint_max_[j] ? "positive" : "negative");
            *error = buf;
            return false;
        }
    }
    return true;
}

// Lines, arcs, probes and rigid taps: checked, then queued as motion fills the planner segment.
bool SimMotion::cmd_move(const emcmot_command_t &c, std::string *error)
{
    static const char *words[] = {"Linear", "Circular", "Probe", "Rigid tap"};
    int k = c.command == EMCMOT_SET_CIRCLE ? 1 : c.command == EMCMOT_PROBE ? 2 : c.command == EMCMOT_RIGID_TAP ? 3 : 0;
    if (!check_move(c, words[k], error)) return false;
    if (c.command == EMCMOT_RIGID_TAP && (c.spindle < 0 || c.spindle >= in_.num_spindles)) {
        *error = "rigid tap on non-existent spindle " + std::to_string(c.spindle);
        return false;
    }
    return queue_move(c, error);
}

bool SimMotion::queue_move(const emcmot_command_t &c, std::string *error)
{
    if (done()) {
        tp_planner_get_pos(tp_, &queued_end_);
        if (c.command == EMCMOT_RIGID_TAP) tp_planner_set_pos(tp_, &queued_end_);
    }
    tp_segment_t seg;
    memset(&seg, 0, sizeof seg);
    seg.kind = c.command == EMCMOT_SET_CIRCLE ? TP_SEG_CIRCLE : c.command == EMCMOT_RIGID_TAP ? TP_SEG_RIGID_TAP : TP_SEG_LINE;
    seg.motion_type = (tp_motion_type_t)c.motion_type;
    if (c.command == EMCMOT_PROBE && c.motion_type == 0) seg.motion_type = TP_MOTION_PROBING;
    if (c.command == EMCMOT_RIGID_TAP && c.motion_type == 0) seg.motion_type = TP_MOTION_FEED;
    seg.end = c.pos;
    seg.center = c.center;
    seg.normal = c.normal;
    seg.turn = c.turn;
    seg.vel = c.vel;
    seg.ini_maxvel = c.ini_maxvel;
    seg.acc = c.acc;
    seg.jerk = c.jerk;
    seg.enables = (fs_enabled_ ? TP_ENABLE_FS : 0) | (fh_enabled_ ? TP_ENABLE_FH : 0) |
                  (af_enabled_ ? TP_ENABLE_AF : 0) | (in_.num_spindles > 0 ? TP_ENABLE_SS : 0);
    seg.atspeed = seg.motion_type != TP_MOTION_TRAVERSE && atspeed_next_feed_;
    seg.indexer_jnum = -1;
    seg.tap_uu_per_rev = c.tap_pitch != 0.0 ? c.tap_pitch : spindle_sync_;
    seg.id = c.id;
    seg.tag = c.tag;
    tp_result_t r = tp_planner_add(tp_, &seg);
    if (r == TP_ZERO_LENGTH) return true;
    if (r != TP_OK) {
        *error = "can't add move at line " + std::to_string(c.id) + " (planner result " + std::to_string((int)r) + ")";
        return false;
    }
    if (seg.atspeed) atspeed_next_feed_ = false;
    queued_end_ = c.pos;
    return true;
}

// The ideal spindle: at the commanded speed (constant surface speed from X) at once; an armed
// index resets the revolutions at the next whole turn.
void SimMotion::spindle_step(const tp_cycle_out_t &out)
{
    double dt = limits_.cycle_time;
    for (int s = 0; s < in_.num_spindles; s++) {
        tp_spindle_in_t &sp = in_.spindle[s];
        double rpm = spindle_rpm_[s];
        if (css_factor_[s] > 0.0 && rpm != 0.0) {
            double r = std::fabs(out.pos.tran.x - css_xoffset_[s]);
            double css = r > 1e-9 ? css_factor_[s] / r : std::fabs(rpm);
            rpm = std::copysign(std::fmin(std::fabs(rpm), css), rpm);
        }
        if (out.spindle_reverse[s]) rpm = -rpm;
        double rps = rpm / 60.0, before = sp.revs;
        sp.speed_cmd_rps = sp.speed_rps = rps;
        sp.revs += rps * dt;
        if (out.arm_index[s]) sp.index_enable = 1;
        else if (sp.index_enable && std::floor(sp.revs) != std::floor(before)) {
            sp.revs -= std::floor(std::fmax(sp.revs, before));
            sp.index_enable = 0;
        }
    }
}

SimSample SimMotion::cycle()
{
    tp_cycle_out_t out;
    memset(&out, 0, sizeof out);
    tp_planner_run_cycle(tp_, &in_, &out);
    spindle_step(out);
    if (planner_type_pending_ >= 0 && out.done) {
        emcmot_command_t c = {};
        c.planner_type = planner_type_pending_;
        std::string ignored;
        cmd_planner_type(c, &ignored);
    }
    SimSample s;
    s.pos = out.pos;
    s.vel = out.current_vel;
    s.requested_vel = out.requested_vel;
    s.line = out.exec_id;
    s.motion_type = out.motion_type;
    return s;
}
