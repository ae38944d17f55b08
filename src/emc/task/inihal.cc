// inihal.cc: the ini.* pins: created with the INI values, compared every task cycle, changes sent to motion.
#include "inihal.hh"

namespace {
const char AXIS_NAMES[] = "xyzabcuvw";
emcmot_command_t cmd(emcmot_command_code_t c) { return MotionTranslator::make(c); }
}

bool IniHal::create(std::string *error)
{
    id_ = hal_init("inihal");
    if (id_ < 0) { *error = "inihal: hal_init failed"; return false; }
    pins_ = static_cast<Pins *>(hal_malloc(sizeof(Pins)));
    if (!pins_ || !create_pins(error)) {
        if (error->empty()) *error = "inihal: out of HAL memory";
        return false;
    }
    store();
    if (hal_ready(id_) != 0) { *error = "inihal: hal_ready failed"; return false; }
    return true;
}

void IniHal::destroy()
{
    if (id_ >= 0) hal_exit(id_);
    id_ = -1;
    pins_ = nullptr;
}

bool IniHal::create_pins(std::string *error)
{
    bool ok = true;
    auto f = [&](hal_float_t **p, const std::string &name) {
        ok = ok && hal_pin_float_newf(HAL_IN, p, id_, "ini.%s", name.c_str()) == 0;
        if (!ok && error->empty()) *error = "inihal: can't create pin ini." + name;
    };
    auto s = [&](hal_s32_t **p, const std::string &name) {
        ok = ok && hal_pin_s32_newf(HAL_IN, p, id_, "ini.%s", name.c_str()) == 0;
        if (!ok && error->empty()) *error = "inihal: can't create pin ini." + name;
    };
    auto b = [&](hal_bit_t **p, const std::string &name) {
        ok = ok && hal_pin_bit_newf(HAL_IN, p, id_, "ini.%s", name.c_str()) == 0;
        if (!ok && error->empty()) *error = "inihal: can't create pin ini." + name;
    };
    for (int j = 0; j < cfg_.joints; j++) {
        JointPins &p = pins_->joint[j];
        std::string n = std::to_string(j) + ".";
        f(&p.ferror, n + "ferror"); f(&p.min_ferror, n + "min_ferror"); f(&p.backlash, n + "backlash");
        f(&p.min_limit, n + "min_limit"); f(&p.max_limit, n + "max_limit");
        f(&p.max_velocity, n + "max_velocity"); f(&p.max_acceleration, n + "max_acceleration");
        f(&p.max_jerk, n + "max_jerk"); f(&p.home, n + "home"); f(&p.home_offset, n + "home_offset");
        s(&p.home_sequence, n + "home_sequence");
    }
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        AxisPins &p = pins_->axis[a];
        std::string n = std::string(1, AXIS_NAMES[a]) + ".";
        f(&p.min_limit, n + "min_limit"); f(&p.max_limit, n + "max_limit");
        f(&p.max_velocity, n + "max_velocity"); f(&p.max_acceleration, n + "max_acceleration");
        f(&p.max_jerk, n + "max_jerk");
    }
    TrajPins &t = pins_->traj;
    b(&t.arc_blend_enable, "traj_arc_blend_enable");
    b(&t.arc_blend_fallback_enable, "traj_arc_blend_fallback_enable");
    f(&t.arc_blend_gap_cycles, "traj_arc_blend_gap_cycles");
    s(&t.arc_blend_optimization_depth, "traj_arc_blend_optimization_depth");
    f(&t.arc_blend_ramp_freq, "traj_arc_blend_ramp_freq");
    f(&t.arc_blend_tangent_kink_ratio, "traj_arc_blend_tangent_kink_ratio");
    f(&t.default_acceleration, "traj_default_acceleration");
    f(&t.default_velocity, "traj_default_velocity");
    f(&t.max_acceleration, "traj_max_acceleration");
    f(&t.max_jerk, "traj_max_jerk");
    f(&t.max_velocity, "traj_max_velocity");
    s(&t.planner_type, "traj_planner_type");
    f(&t.scurve_peak_scale, "traj_scurve_peak_scale");
    return ok;
}

// Pins := the configuration (axes not in COORDINATES read 0).
void IniHal::store()
{
    for (int j = 0; j < cfg_.joints; j++) {
        JointPins &p = pins_->joint[j];
        const JointConfig &c = cfg_.joint[j];
        *p.ferror = c.ferror; *p.min_ferror = c.min_ferror; *p.backlash = c.backlash;
        *p.min_limit = c.min_limit; *p.max_limit = c.max_limit;
        *p.max_velocity = c.max_velocity; *p.max_acceleration = c.max_acceleration;
        *p.max_jerk = c.max_jerk; *p.home = c.home; *p.home_offset = c.home_offset;
        *p.home_sequence = c.home_sequence;
    }
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        AxisPins &p = pins_->axis[a];
        bool used = cfg_.axis_mask & (1 << a);
        AxisConfig &c = cfg_.axis[a];
        if (!used) c.min_limit = c.max_limit = c.max_velocity = c.max_acceleration = c.max_jerk = 0;
        *p.min_limit = used ? c.min_limit : 0; *p.max_limit = used ? c.max_limit : 0;
        *p.max_velocity = used ? c.max_velocity : 0;
        *p.max_acceleration = used ? c.max_acceleration : 0;
        *p.max_jerk = used ? c.max_jerk : 0;
    }
    TrajPins &t = pins_->traj;
    *t.arc_blend_enable = cfg_.arc_blend_enable;
    *t.arc_blend_fallback_enable = cfg_.arc_blend_fallback_enable;
    *t.arc_blend_gap_cycles = cfg_.arc_blend_gap_cycles;
    *t.arc_blend_optimization_depth = cfg_.arc_blend_optimization_depth;
    *t.arc_blend_ramp_freq = cfg_.arc_blend_ramp_freq;
    *t.arc_blend_tangent_kink_ratio = cfg_.arc_blend_kink_ratio;
    *t.default_acceleration = cfg_.default_linear_acceleration;
    *t.default_velocity = cfg_.default_linear_velocity;
    *t.max_acceleration = cfg_.max_linear_acceleration;
    *t.max_jerk = cfg_.max_linear_jerk;
    *t.max_velocity = cfg_.max_linear_velocity;
    *t.planner_type = cfg_.planner_type;
    *t.scurve_peak_scale = cfg_.scurve_peak_scale;
}

// Update *have from pin; true when it changed.
template <class T, class P>
static bool changed(T &have, P *pin)
{
    if (have == (T)*pin) return false;
    have = (T)*pin;
    return true;
}

void IniHal::check_joint(int j, MotionCommands &out)
{
    JointPins &p = pins_->joint[j];
    JointConfig &c = cfg_.joint[j];
    emcmot_command_t m;
    if (changed(c.ferror, p.ferror)) { m = cmd(EMCMOT_SET_JOINT_MAX_FERROR); m.joint = j; m.max_ferror = c.ferror; out.push_back(m); }
    if (changed(c.min_ferror, p.min_ferror)) { m = cmd(EMCMOT_SET_JOINT_MIN_FERROR); m.joint = j; m.min_ferror = c.min_ferror; out.push_back(m); }
    if (changed(c.backlash, p.backlash)) { m = cmd(EMCMOT_SET_JOINT_BACKLASH); m.joint = j; m.backlash = c.backlash; out.push_back(m); }
    bool lim = changed(c.min_limit, p.min_limit);
    lim = changed(c.max_limit, p.max_limit) || lim;
    if (lim) { m = cmd(EMCMOT_SET_JOINT_POSITION_LIMITS); m.joint = j; m.min_limit = c.min_limit; m.max_limit = c.max_limit; out.push_back(m); }
    if (changed(c.max_velocity, p.max_velocity)) { m = cmd(EMCMOT_SET_JOINT_VEL_LIMIT); m.joint = j; m.vel = c.max_velocity; out.push_back(m); }
    if (changed(c.max_acceleration, p.max_acceleration)) { m = cmd(EMCMOT_SET_JOINT_ACC_LIMIT); m.joint = j; m.acc = c.max_acceleration; out.push_back(m); }
    if (changed(c.max_jerk, p.max_jerk)) { m = cmd(EMCMOT_SET_JOINT_JERK_LIMIT); m.joint = j; m.jerk = c.max_jerk; out.push_back(m); }
    bool home = changed(c.home, p.home);
    home = changed(c.home_offset, p.home_offset) || home;
    home = changed(c.home_sequence, p.home_sequence) || home;
    if (home) {
        m = cmd(EMCMOT_UPDATE_JOINT_HOMING_PARAMS);
        m.joint = j; m.home = c.home; m.home_offset = c.home_offset; m.home_sequence = c.home_sequence;
        out.push_back(m);
    }
}

void IniHal::check_axis(int a, MotionCommands &out)
{
    AxisPins &p = pins_->axis[a];
    AxisConfig &c = cfg_.axis[a];
    emcmot_command_t m;
    bool lim = changed(c.min_limit, p.min_limit);
    lim = changed(c.max_limit, p.max_limit) || lim;
    if (lim) { m = cmd(EMCMOT_SET_AXIS_POSITION_LIMITS); m.axis = a; m.min_limit = c.min_limit; m.max_limit = c.max_limit; out.push_back(m); }
    double keep = 1.0 - c.offset_av_ratio;
    if (changed(c.max_velocity, p.max_velocity)) {
        m = cmd(EMCMOT_SET_AXIS_VEL_LIMIT); m.axis = a;
        m.vel = c.max_velocity * keep; m.ext_offset_vel = c.max_velocity * c.offset_av_ratio; out.push_back(m);
    }
    if (changed(c.max_acceleration, p.max_acceleration)) {
        m = cmd(EMCMOT_SET_AXIS_ACC_LIMIT); m.axis = a;
        m.acc = c.max_acceleration * keep; m.ext_offset_acc = c.max_acceleration * c.offset_av_ratio; out.push_back(m);
    }
    if (changed(c.max_jerk, p.max_jerk)) { m = cmd(EMCMOT_SET_AXIS_JERK_LIMIT); m.axis = a; m.jerk = c.max_jerk; out.push_back(m); }
}

void IniHal::check_traj(MotionCommands &out)
{
    TrajPins &t = pins_->traj;
    MachineConfig &c = cfg_;
    emcmot_command_t m;
    bool blend = changed(c.arc_blend_enable, t.arc_blend_enable);
    blend = changed(c.arc_blend_fallback_enable, t.arc_blend_fallback_enable) || blend;
    blend = changed(c.arc_blend_gap_cycles, t.arc_blend_gap_cycles) || blend;
    blend = changed(c.arc_blend_optimization_depth, t.arc_blend_optimization_depth) || blend;
    blend = changed(c.arc_blend_ramp_freq, t.arc_blend_ramp_freq) || blend;
    blend = changed(c.arc_blend_kink_ratio, t.arc_blend_tangent_kink_ratio) || blend;
    if (blend) {
        m = cmd(EMCMOT_SETUP_ARC_BLENDS);
        m.arc_blend_enable = c.arc_blend_enable; m.arc_blend_fallback_enable = c.arc_blend_fallback_enable;
        m.arc_blend_optimization_depth = c.arc_blend_optimization_depth; m.arc_blend_gap_cycles = c.arc_blend_gap_cycles;
        m.arc_blend_ramp_freq = c.arc_blend_ramp_freq; m.arc_blend_tangent_kink_ratio = c.arc_blend_kink_ratio;
        out.push_back(m);
    }
    if (changed(c.default_linear_acceleration, t.default_acceleration)) { m = cmd(EMCMOT_SET_ACC); m.acc = c.default_linear_acceleration; out.push_back(m); }
    if (changed(c.default_linear_velocity, t.default_velocity)) { m = cmd(EMCMOT_SET_VEL); m.vel = 0; m.ini_maxvel = c.default_linear_velocity; out.push_back(m); }
    changed(c.max_linear_acceleration, t.max_acceleration);
    bool jerk = changed(c.max_linear_jerk, t.max_jerk);
    if (jerk) { m = cmd(EMCMOT_SET_JERK); m.jerk = c.max_linear_jerk; out.push_back(m); }
    if (changed(c.max_linear_velocity, t.max_velocity)) { m = cmd(EMCMOT_SET_VEL_LIMIT); m.vel = c.max_linear_velocity; out.push_back(m); }
    if (changed(c.planner_type, t.planner_type) || jerk) {
        m = cmd(EMCMOT_SET_PLANNER_TYPE);
        m.planner_type = c.max_linear_jerk < 1.0 ? 0 : c.planner_type;
        out.push_back(m);
    }
    if (changed(c.scurve_peak_scale, t.scurve_peak_scale)) { m = cmd(EMCMOT_SET_SCURVE_PEAK_SCALE); m.scale = c.scurve_peak_scale; out.push_back(m); }
}

void IniHal::check(MotionCommands &out)
{
    if (!pins_) return;
    for (int j = 0; j < cfg_.joints; j++) check_joint(j, out);
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) check_axis(a, out);
    check_traj(out);
}
