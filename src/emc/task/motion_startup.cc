// motion_startup.cc: the configuration stream task sends motion once attached (LinuxCNC's emctask start-up order).
#include "motion_translate.hh"

#include <cmath>

#include "comp_file.h"

MotionTranslator::MotionTranslator(const MachineConfig &cfg)
    : cfg_(cfg), min_limit_(cfg.joints, 0.0), max_limit_(cfg.joints, 0.0)
{
}

emcmot_command_t MotionTranslator::make(emcmot_command_code_t code)
{
    emcmot_command_t c;
    emcmot_command_init(&c, code);
    return c;
}

int motion_home_flags(const JointConfig &j)
{
    int f = 0;
    if (j.home_ignore_limits) f |= EMCMOT_HOME_IGNORE_LIMITS;
    if (j.home_use_index) f |= EMCMOT_HOME_USE_INDEX;
    if (j.home_is_shared) f |= EMCMOT_HOME_IS_SHARED;
    if (j.locking_indexer) f |= EMCMOT_HOME_UNLOCK_FIRST;
    if (j.home_absolute_encoder >= 1) f |= EMCMOT_HOME_ABSOLUTE_ENCODER | EMCMOT_HOME_NO_REHOME;
    if (j.home_absolute_encoder == 2) f |= EMCMOT_HOME_NO_FINAL_MOVE;
    if (j.home_index_no_encoder_reset) f |= EMCMOT_HOME_INDEX_NO_ENCODER_RESET;
    return f;
}

// Trajectory-wide settings: counts, velocities, planner, blends, overrides, world home.
void MotionTranslator::startup_traj(MotionCommands &out) const
{
    emcmot_command_t c = make(EMCMOT_SET_NUM_JOINTS);
    c.count = cfg_.joints;
    out.push_back(c);
    c = make(EMCMOT_SET_NUM_SPINDLES);
    c.count = cfg_.spindles;
    out.push_back(c);
    c = make(EMCMOT_SET_VEL);
    c.vel = 0;
    c.ini_maxvel = cfg_.default_linear_velocity;
    out.push_back(c);
    c = make(EMCMOT_SET_VEL_LIMIT);
    c.vel = cfg_.max_linear_velocity;
    out.push_back(c);
    c = make(EMCMOT_SET_ACC);
    c.acc = cfg_.default_linear_acceleration;
    out.push_back(c);
    c = make(EMCMOT_SET_JERK);
    c.jerk = cfg_.max_linear_jerk;
    out.push_back(c);
    c = make(EMCMOT_SET_PLANNER_TYPE);
    c.planner_type = cfg_.planner_type;
    out.push_back(c);
    c = make(EMCMOT_SET_SCURVE_PEAK_SCALE);
    c.scale = cfg_.scurve_peak_scale;
    out.push_back(c);
    c = make(EMCMOT_SETUP_ARC_BLENDS);
    c.arc_blend_enable = cfg_.arc_blend_enable;
    c.arc_blend_fallback_enable = cfg_.arc_blend_fallback_enable;
    c.arc_blend_optimization_depth = cfg_.arc_blend_optimization_depth;
    c.arc_blend_gap_cycles = cfg_.arc_blend_gap_cycles;
    c.arc_blend_ramp_freq = cfg_.arc_blend_ramp_freq;
    c.arc_blend_tangent_kink_ratio = cfg_.arc_blend_kink_ratio;
    out.push_back(c);
    c = make(EMCMOT_SET_MAX_FEED_OVERRIDE);
    c.scale = cfg_.max_feed_override;
    out.push_back(c);
    c = make(EMCMOT_SET_PROBE_ERR_INHIBIT);
    c.probe_jog_err_inhibit = cfg_.no_probe_jog_error;
    c.probe_home_err_inhibit = cfg_.no_probe_home_error;
    out.push_back(c);
    c = make(EMCMOT_SET_WORLD_HOME);
    const double *h = cfg_.world_home;
    c.pos.tran.x = h[0]; c.pos.tran.y = h[1]; c.pos.tran.z = h[2];
    c.pos.a = h[3]; c.pos.b = h[4]; c.pos.c = h[5];
    c.pos.u = h[6]; c.pos.v = h[7]; c.pos.w = h[8];
    out.push_back(c);
}

// Set joint limits (LinuxCNC sends min and max one after the other, each with the other's current value).
void MotionTranslator::set_joint_limits(int joint, double min, double max, MotionCommands &out)
{
    emcmot_command_t c = make(EMCMOT_SET_JOINT_POSITION_LIMITS);
    c.joint = joint;
    c.min_limit = min;
    c.max_limit = max;
    if (joint >= 0 && joint < (int)min_limit_.size()) {
        min_limit_[joint] = min;
        max_limit_[joint] = max;
    }
    out.push_back(c);
}

void MotionTranslator::startup_joint(int j, MotionCommands &out)
{
    const JointConfig &jc = cfg_.joint[j];
    emcmot_command_t c = make(EMCMOT_SET_JOINT_BACKLASH);
    c.joint = j;
    c.backlash = jc.backlash;
    out.push_back(c);
    set_joint_limits(j, jc.min_limit, max_limit_[j], out);
    set_joint_limits(j, jc.min_limit, jc.max_limit, out);
    c = make(EMCMOT_SET_JOINT_MAX_FERROR);
    c.joint = j;
    c.max_ferror = jc.ferror;
    out.push_back(c);
    c = make(EMCMOT_SET_JOINT_MIN_FERROR);
    c.joint = j;
    c.min_ferror = jc.min_ferror;
    out.push_back(c);
    c = make(EMCMOT_SET_JOINT_HOMING_PARAMS);
    c.joint = j;
    c.home_offset = jc.home_offset;
    c.home = jc.home;
    c.home_final_vel = jc.home_final_vel;
    c.home_search_vel = jc.home_search_vel;
    c.home_latch_vel = jc.home_latch_vel;
    c.home_flags = motion_home_flags(jc);
    c.home_sequence = jc.home_sequence;
    c.volatile_home = jc.volatile_home;
    out.push_back(c);
    c = make(EMCMOT_SET_JOINT_VEL_LIMIT);
    c.joint = j;
    c.vel = jc.max_velocity;
    out.push_back(c);
    c = make(EMCMOT_SET_JOINT_ACC_LIMIT);
    c.joint = j;
    c.acc = jc.max_acceleration;
    out.push_back(c);
    c = make(EMCMOT_SET_JOINT_JERK_LIMIT);
    c.joint = j;
    c.jerk = jc.max_jerk;
    out.push_back(c);
    c = make(EMCMOT_JOINT_ACTIVATE);
    c.joint = j;
    out.push_back(c);
}

void MotionTranslator::startup_axis(int a, MotionCommands &out) const
{
    const AxisConfig &ac = cfg_.axis[a];
    emcmot_command_t c = make(EMCMOT_SET_AXIS_POSITION_LIMITS);
    c.axis = a;
    c.min_limit = ac.min_limit;
    c.max_limit = 0;
    out.push_back(c);
    c.max_limit = ac.max_limit;
    out.push_back(c);
    double keep = 1.0 - ac.offset_av_ratio;
    c = make(EMCMOT_SET_AXIS_VEL_LIMIT);
    c.axis = a;
    c.vel = ac.max_velocity * keep;
    c.ext_offset_vel = ac.max_velocity * ac.offset_av_ratio;
    out.push_back(c);
    c = make(EMCMOT_SET_AXIS_ACC_LIMIT);
    c.axis = a;
    c.acc = ac.max_acceleration * keep;
    c.ext_offset_acc = ac.max_acceleration * ac.offset_av_ratio;
    out.push_back(c);
    c = make(EMCMOT_SET_AXIS_LOCKING_JOINT);
    c.axis = a;
    c.locking_joint = ac.locking_joint;
    out.push_back(c);
    c = make(EMCMOT_SET_AXIS_JERK_LIMIT);
    c.axis = a;
    c.jerk = ac.max_jerk;
    out.push_back(c);
}

void MotionTranslator::startup(MotionCommands &out)
{
    startup_traj(out);
    for (int j = 0; j < cfg_.joints; j++) startup_joint(j, out);
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++)
        if (cfg_.axis_mask & (1 << a)) startup_axis(a, out);
    for (int s = 0; s < cfg_.spindles; s++) {
        const SpindleConfig &sc = cfg_.spindle[s];
        emcmot_command_t c = make(EMCMOT_SET_SPINDLE_PARAMS);
        c.spindle = s;
        c.max_pos_speed = sc.max_pos;
        c.min_pos_speed = sc.min_pos;
        c.max_neg_speed = sc.max_neg;
        c.min_neg_speed = sc.min_neg;
        c.spindle_increment = sc.increment;
        out.push_back(c);
    }
}

void MotionTranslator::motion_abort(MotionCommands &out) const
{
    for (int j = 0; j < EMCMOT_MAX_JOINTS; j++) {
        emcmot_command_t c = make(EMCMOT_JOG_ABORT);
        c.joint = j;
        out.push_back(c);
    }
    out.push_back(make(EMCMOT_ABORT));
}

void MotionTranslator::spindles_off(MotionCommands &out) const
{
    for (int s = 0; s < cfg_.spindles; s++) {
        emcmot_command_t c = make(EMCMOT_SPINDLE_OFF);
        c.spindle = s;
        out.push_back(c);
    }
}

// Path jerk of a move from the last end point to end (0 = no jerk limit configured).
double MotionTranslator::move_jerk(const EmcPose &end) const
{
    double d[CANON_AXES] = {end.tran.x - last_end_.tran.x, end.tran.y - last_end_.tran.y,
                            end.tran.z - last_end_.tran.z, end.a - last_end_.a, end.b - last_end_.b,
                            end.c - last_end_.c, end.u - last_end_.u, end.v - last_end_.v,
                            end.w - last_end_.w};
    canon_axis_limits_t lim = machine_axis_limits(cfg_);
    canon_path_limits_t p;
    canon_line_limits(d, &lim, &p);
    return p.jerk;
}
