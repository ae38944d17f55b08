// motion_translate.cc: the table of NML message -> EMCMOT command handlers.
#include "motion_translate.hh"

#include "comp_file.h"

namespace {

using Ctx = MotionTranslator::Ctx;

template <class M>
const M &as(const Ctx &c) { return *emc_msg_as<M>(&c.msg); }

emcmot_command_t cmd(emcmot_command_code_t code) { return MotionTranslator::make(code); }

// A command that needs only its code.
template <emcmot_command_code_t CODE>
bool plain(Ctx &c) { c.out.push_back(cmd(CODE)); return true; }

// A command that names one joint.
template <class M, emcmot_command_code_t CODE>
bool joint_cmd(Ctx &c)
{
    emcmot_command_t m = cmd(CODE);
    m.joint = as<M>(c).joint;
    c.out.push_back(m);
    return true;
}

bool joint_min_limit(Ctx &c)
{
    const auto &m = as<EMC_JOINT_SET_MIN_POSITION_LIMIT>(c);
    c.self.set_joint_limits(m.joint, m.limit, c.self.joint_max(m.joint), c.out);
    return true;
}

bool joint_max_limit(Ctx &c)
{
    const auto &m = as<EMC_JOINT_SET_MAX_POSITION_LIMIT>(c);
    c.self.set_joint_limits(m.joint, c.self.joint_min(m.joint), m.limit, c.out);
    return true;
}

bool joint_ferror(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SET_JOINT_MAX_FERROR);
    m.joint = as<EMC_JOINT_SET_FERROR>(c).joint;
    m.max_ferror = as<EMC_JOINT_SET_FERROR>(c).ferror;
    c.out.push_back(m);
    return true;
}

bool joint_min_ferror(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SET_JOINT_MIN_FERROR);
    m.joint = as<EMC_JOINT_SET_MIN_FERROR>(c).joint;
    m.min_ferror = as<EMC_JOINT_SET_MIN_FERROR>(c).ferror;
    c.out.push_back(m);
    return true;
}

bool joint_homing_params(Ctx &c)
{
    const auto &h = as<EMC_JOINT_SET_HOMING_PARAMS>(c);
    JointConfig j;
    j.home_ignore_limits = h.ignore_limits;
    j.home_use_index = h.use_index;
    j.home_is_shared = h.is_shared;
    j.locking_indexer = h.locking_indexer;
    j.home_absolute_encoder = h.absolute_encoder;
    j.home_index_no_encoder_reset = h.encoder_does_not_reset;
    emcmot_command_t m = cmd(EMCMOT_SET_JOINT_HOMING_PARAMS);
    m.joint = h.joint;
    m.home = h.home;
    m.home_offset = h.offset;
    m.home_final_vel = h.home_final_vel;
    m.home_search_vel = h.search_vel;
    m.home_latch_vel = h.latch_vel;
    m.home_flags = motion_home_flags(j);
    m.home_sequence = h.home_sequence;
    m.volatile_home = h.volatile_home;
    c.out.push_back(m);
    return true;
}

bool joint_backlash(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SET_JOINT_BACKLASH);
    m.joint = as<EMC_JOINT_SET_BACKLASH>(c).joint;
    m.backlash = as<EMC_JOINT_SET_BACKLASH>(c).backlash;
    c.out.push_back(m);
    return true;
}

bool joint_override_limits(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_OVERRIDE_LIMITS);
    m.joint = as<EMC_JOINT_OVERRIDE_LIMITS>(c).joint;
    m.enable = 1;
    c.out.push_back(m);
    return true;
}

// COMP_FILE rows, one SET_JOINT_COMP each.
bool joint_load_comp(Ctx &c)
{
    const auto &l = as<EMC_JOINT_LOAD_COMP>(c);
    comp_row_t rows[COMP_FILE_MAX_ROWS];
    char why[512];
    int n = comp_file_read(l.file, l.joint, l.type, rows, COMP_FILE_MAX_ROWS, why, sizeof why);
    if (n < 0) {
        if (c.error) *c.error = why;
        return true;
    }
    for (int i = 0; i < n; i++) {
        emcmot_command_t m = cmd(EMCMOT_SET_JOINT_COMP);
        m.joint = l.joint;
        m.comp_nominal = rows[i].nominal;
        m.comp_forward = rows[i].forward;
        m.comp_reverse = rows[i].reverse;
        c.out.push_back(m);
    }
    return true;
}

// Jogs name a joint (jjogmode 1) or an axis (joint -1).
template <class M>
emcmot_command_t jog(const Ctx &c, emcmot_command_code_t code)
{
    const M &j = as<M>(c);
    emcmot_command_t m = cmd(code);
    if (j.jjogmode == EMC_JOG_JOINT) {
        m.joint = j.joint_or_axis;
    } else {
        m.joint = -1;
        m.axis = j.joint_or_axis;
    }
    return m;
}

bool jog_cont(Ctx &c)
{
    emcmot_command_t m = jog<EMC_JOG_CONT>(c, EMCMOT_JOG_CONT);
    m.vel = as<EMC_JOG_CONT>(c).vel;
    c.out.push_back(m);
    return true;
}

bool jog_incr(Ctx &c)
{
    emcmot_command_t m = jog<EMC_JOG_INCR>(c, EMCMOT_JOG_INCR);
    m.vel = as<EMC_JOG_INCR>(c).vel;
    m.offset = as<EMC_JOG_INCR>(c).incr;
    c.out.push_back(m);
    return true;
}

bool jog_abs(Ctx &c)
{
    emcmot_command_t m = jog<EMC_JOG_ABS>(c, EMCMOT_JOG_ABS);
    m.vel = as<EMC_JOG_ABS>(c).vel;
    m.offset = as<EMC_JOG_ABS>(c).pos;
    c.out.push_back(m);
    return true;
}

bool jog_stop(Ctx &c)
{
    c.out.push_back(jog<EMC_JOG_STOP>(c, EMCMOT_JOG_ABORT));
    return true;
}

bool traj_set_mode(Ctx &c)
{
    int mode = as<EMC_TRAJ_SET_MODE>(c).mode;
    c.out.push_back(cmd(mode == EMC_TRAJ_MODE_COORD ? EMCMOT_COORD
                        : mode == EMC_TRAJ_MODE_TELEOP ? EMCMOT_TELEOP : EMCMOT_FREE));
    return true;
}

bool teleop_enable(Ctx &c)
{
    c.out.push_back(cmd(as<EMC_TRAJ_SET_TELEOP_ENABLE>(c).enable ? EMCMOT_TELEOP : EMCMOT_FREE));
    return true;
}

bool traj_velocity(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SET_VEL);
    m.vel = as<EMC_TRAJ_SET_VELOCITY>(c).velocity;
    m.ini_maxvel = as<EMC_TRAJ_SET_VELOCITY>(c).ini_maxvel;
    c.out.push_back(m);
    return true;
}

bool traj_acceleration(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SET_ACC);
    m.acc = as<EMC_TRAJ_SET_ACCELERATION>(c).acceleration;
    c.out.push_back(m);
    return true;
}

bool traj_max_velocity(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SET_VEL_LIMIT);
    m.vel = as<EMC_TRAJ_SET_MAX_VELOCITY>(c).velocity;
    c.out.push_back(m);
    return true;
}

template <class M, emcmot_command_code_t CODE>
bool scale_cmd(Ctx &c)
{
    emcmot_command_t m = cmd(CODE);
    m.scale = as<M>(c).scale;
    c.out.push_back(m);
    return true;
}

bool spindle_scale(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SPINDLE_SCALE);
    m.spindle = as<EMC_TRAJ_SET_SPINDLE_SCALE>(c).spindle;
    m.scale = as<EMC_TRAJ_SET_SPINDLE_SCALE>(c).scale;
    c.out.push_back(m);
    return true;
}

template <class M, emcmot_command_code_t CODE>
bool enable_cmd(Ctx &c)
{
    emcmot_command_t m = cmd(CODE);
    m.enable = as<M>(c).mode ? 1 : 0;
    c.out.push_back(m);
    return true;
}

bool so_enable(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SS_ENABLE);
    m.enable = as<EMC_TRAJ_SET_SO_ENABLE>(c).mode ? 1 : 0;
    m.spindle = as<EMC_TRAJ_SET_SO_ENABLE>(c).spindle;
    c.out.push_back(m);
    return true;
}

bool adaptive(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_AF_ENABLE);
    m.enable = as<EMC_MOTION_ADAPTIVE>(c).status ? 1 : 0;
    c.out.push_back(m);
    return true;
}

bool traj_abort(Ctx &c)
{
    c.self.motion_abort(c.out);
    return true;
}

bool linear_move(Ctx &c)
{
    const auto &l = as<EMC_TRAJ_LINEAR_MOVE>(c);
    emcmot_command_t m = cmd(EMCMOT_SET_LINE);
    m.pos = l.end;
    m.id = l.tag.line_number;
    m.motion_type = l.type;
    m.vel = l.vel;
    m.ini_maxvel = l.ini_maxvel;
    m.acc = l.acc;
    m.jerk = c.self.jerk_to(l.end);
    m.tag = l.tag;
    c.out.push_back(m);
    return true;
}

bool circular_move(Ctx &c)
{
    const auto &a = as<EMC_TRAJ_CIRCULAR_MOVE>(c);
    emcmot_command_t m = cmd(EMCMOT_SET_CIRCLE);
    m.pos = a.end;
    m.center = a.center;
    m.normal = a.normal;
    m.turn = a.turn;
    m.id = a.tag.line_number;
    m.motion_type = a.type;
    m.vel = a.vel;
    m.ini_maxvel = a.ini_maxvel;
    m.acc = a.acc;
    m.jerk = c.self.jerk_to(a.end);
    m.tag = a.tag;
    c.out.push_back(m);
    return true;
}

bool probe(Ctx &c)
{
    const auto &p = as<EMC_TRAJ_PROBE>(c);
    emcmot_command_t m = cmd(EMCMOT_PROBE);
    m.pos = p.pos;
    m.id = p.tag.line_number;
    m.motion_type = p.type;
    m.probe_type = p.probe_type;
    m.vel = p.vel;
    m.ini_maxvel = p.ini_maxvel;
    m.acc = p.acc;
    m.jerk = c.self.jerk_to(p.pos);
    m.tag = p.tag;
    c.out.push_back(m);
    return true;
}

bool rigid_tap(Ctx &c)
{
    const auto &t = as<EMC_TRAJ_RIGID_TAP>(c);
    emcmot_command_t m = cmd(EMCMOT_RIGID_TAP);
    m.pos = t.pos;
    m.id = t.tag.line_number;
    m.vel = t.vel;
    m.ini_maxvel = t.ini_maxvel;
    m.acc = t.acc;
    m.scale = t.scale;
    m.tag = t.tag;
    c.out.push_back(m);
    return true;
}

bool term_cond(Ctx &c)
{
    const auto &t = as<EMC_TRAJ_SET_TERM_COND>(c);
    emcmot_command_t m = cmd(EMCMOT_SET_TERM_COND);
    m.term_cond = t.cond;
    m.tolerance = t.tolerance;
    c.out.push_back(m);
    if (t.planner_type >= 0) {
        m = cmd(EMCMOT_SET_PLANNER_TYPE);
        m.planner_type = t.planner_type;
        c.out.push_back(m);
        m = cmd(EMCMOT_SET_SCURVE_PEAK_SCALE);
        m.scale = t.scurve_peak_scale;
        c.out.push_back(m);
    }
    return true;
}

bool spindle_sync(Ctx &c)
{
    const auto &s = as<EMC_TRAJ_SET_SPINDLESYNC>(c);
    emcmot_command_t m = cmd(EMCMOT_SET_SPINDLESYNC);
    m.spindle = s.spindle;
    m.spindle_sync = s.feed_per_revolution;
    m.sync_velocity_mode = s.velocity_mode;
    c.out.push_back(m);
    return true;
}

bool tool_offset(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SET_OFFSET);
    m.pos = as<EMC_TRAJ_SET_OFFSET>(c).offset;
    c.out.push_back(m);
    return true;
}

bool set_dout(Ctx &c)
{
    const auto &d = as<EMC_MOTION_SET_DOUT>(c);
    emcmot_command_t m = cmd(EMCMOT_SET_DOUT);
    m.io_index = d.index;
    m.now = d.now;
    m.dout_start = d.start;
    m.dout_end = d.end;
    c.out.push_back(m);
    return true;
}

bool set_aout(Ctx &c)
{
    const auto &a = as<EMC_MOTION_SET_AOUT>(c);
    emcmot_command_t m = cmd(EMCMOT_SET_AOUT);
    m.io_index = a.index;
    m.now = a.now;
    m.aout_start = a.start;
    m.aout_end = a.end;
    c.out.push_back(m);
    return true;
}

bool spindle_on(Ctx &c)
{
    const auto &s = as<EMC_SPINDLE_ON>(c);
    emcmot_command_t m = cmd(EMCMOT_SPINDLE_ON);
    m.spindle = s.spindle;
    m.speed = s.speed;
    m.css_factor = s.factor;
    m.css_xoffset = s.xoffset;
    m.wait_for_at_speed = s.wait_for_spindle_at_speed;
    c.out.push_back(m);
    return true;
}

bool spindle_off(Ctx &c)
{
    emcmot_command_t m = cmd(EMCMOT_SPINDLE_OFF);
    m.spindle = as<EMC_SPINDLE_OFF>(c).spindle;
    m.wait_for_at_speed = as<EMC_SPINDLE_OFF>(c).wait_for_spindle_at_speed;
    c.out.push_back(m);
    return true;
}

template <class M, emcmot_command_code_t CODE>
bool spindle_cmd(Ctx &c)
{
    emcmot_command_t m = cmd(CODE);
    m.spindle = as<M>(c).spindle;
    c.out.push_back(m);
    return true;
}

// Increase/decrease happen in steps; "constant" ends nothing that is still running.
bool spindle_constant(Ctx &) { return true; }

bool spindle_orient(Ctx &c)
{
    const auto &o = as<EMC_SPINDLE_ORIENT>(c);
    emcmot_command_t m = cmd(EMCMOT_SPINDLE_ORIENT);
    m.spindle = o.spindle;
    m.orientation = o.orientation;
    m.orient_mode = o.mode;
    c.out.push_back(m);
    return true;
}

const MotionTranslator::Entry TABLE[] = {
    {EMC_JOINT_SET_MIN_POSITION_LIMIT_TYPE, joint_min_limit},
    {EMC_JOINT_SET_MAX_POSITION_LIMIT_TYPE, joint_max_limit},
    {EMC_JOINT_SET_FERROR_TYPE, joint_ferror},
    {EMC_JOINT_SET_MIN_FERROR_TYPE, joint_min_ferror},
    {EMC_JOINT_SET_HOMING_PARAMS_TYPE, joint_homing_params},
    {EMC_JOINT_SET_BACKLASH_TYPE, joint_backlash},
    {EMC_JOINT_HALT_TYPE, joint_cmd<EMC_JOINT_HALT, EMCMOT_JOG_ABORT>},
    {EMC_JOINT_HOME_TYPE, joint_cmd<EMC_JOINT_HOME, EMCMOT_JOINT_HOME>},
    {EMC_JOINT_UNHOME_TYPE, joint_cmd<EMC_JOINT_UNHOME, EMCMOT_JOINT_UNHOME>},
    {EMC_JOINT_OVERRIDE_LIMITS_TYPE, joint_override_limits},
    {EMC_JOINT_LOAD_COMP_TYPE, joint_load_comp},
    {EMC_JOG_CONT_TYPE, jog_cont},
    {EMC_JOG_INCR_TYPE, jog_incr},
    {EMC_JOG_ABS_TYPE, jog_abs},
    {EMC_JOG_STOP_TYPE, jog_stop},
    {EMC_TRAJ_SET_MODE_TYPE, traj_set_mode},
    {EMC_TRAJ_SET_TELEOP_ENABLE_TYPE, teleop_enable},
    {EMC_TRAJ_SET_VELOCITY_TYPE, traj_velocity},
    {EMC_TRAJ_SET_ACCELERATION_TYPE, traj_acceleration},
    {EMC_TRAJ_SET_MAX_VELOCITY_TYPE, traj_max_velocity},
    {EMC_TRAJ_SET_SCALE_TYPE, scale_cmd<EMC_TRAJ_SET_SCALE, EMCMOT_FEED_SCALE>},
    {EMC_TRAJ_SET_RAPID_SCALE_TYPE, scale_cmd<EMC_TRAJ_SET_RAPID_SCALE, EMCMOT_RAPID_SCALE>},
    {EMC_TRAJ_SET_SPINDLE_SCALE_TYPE, spindle_scale},
    {EMC_TRAJ_SET_FO_ENABLE_TYPE, enable_cmd<EMC_TRAJ_SET_FO_ENABLE, EMCMOT_FS_ENABLE>},
    {EMC_TRAJ_SET_FH_ENABLE_TYPE, enable_cmd<EMC_TRAJ_SET_FH_ENABLE, EMCMOT_FH_ENABLE>},
    {EMC_TRAJ_SET_SO_ENABLE_TYPE, so_enable},
    {EMC_MOTION_ADAPTIVE_TYPE, adaptive},
    {EMC_TRAJ_ABORT_TYPE, traj_abort},
    {EMC_TRAJ_PAUSE_TYPE, plain<EMCMOT_PAUSE>},
    {EMC_TRAJ_RESUME_TYPE, plain<EMCMOT_RESUME>},
    {EMC_TRAJ_LINEAR_MOVE_TYPE, linear_move},
    {EMC_TRAJ_CIRCULAR_MOVE_TYPE, circular_move},
    {EMC_TRAJ_PROBE_TYPE, probe},
    {EMC_TRAJ_RIGID_TAP_TYPE, rigid_tap},
    {EMC_TRAJ_SET_TERM_COND_TYPE, term_cond},
    {EMC_TRAJ_SET_SPINDLESYNC_TYPE, spindle_sync},
    {EMC_TRAJ_SET_OFFSET_TYPE, tool_offset},
    {EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG_TYPE, plain<EMCMOT_CLEAR_PROBE_FLAGS>},
    {EMC_MOTION_SET_DOUT_TYPE, set_dout},
    {EMC_MOTION_SET_AOUT_TYPE, set_aout},
    {EMC_SPINDLE_ON_TYPE, spindle_on},
    {EMC_SPINDLE_OFF_TYPE, spindle_off},
    {EMC_SPINDLE_INCREASE_TYPE, spindle_cmd<EMC_SPINDLE_INCREASE, EMCMOT_SPINDLE_INCREASE>},
    {EMC_SPINDLE_DECREASE_TYPE, spindle_cmd<EMC_SPINDLE_DECREASE, EMCMOT_SPINDLE_DECREASE>},
    {EMC_SPINDLE_CONSTANT_TYPE, spindle_constant},
    {EMC_SPINDLE_BRAKE_RELEASE_TYPE, spindle_cmd<EMC_SPINDLE_BRAKE_RELEASE, EMCMOT_SPINDLE_BRAKE_RELEASE>},
    {EMC_SPINDLE_BRAKE_ENGAGE_TYPE, spindle_cmd<EMC_SPINDLE_BRAKE_ENGAGE, EMCMOT_SPINDLE_BRAKE_ENGAGE>},
    {EMC_SPINDLE_ORIENT_TYPE, spindle_orient},
    {EMC_TASK_PLAN_REVERSE_TYPE, plain<EMCMOT_REVERSE>},
    {EMC_TASK_PLAN_FORWARD_TYPE, plain<EMCMOT_FORWARD>},
};

}  // namespace

const MotionTranslator::Entry *MotionTranslator::table(size_t *count)
{
    *count = sizeof TABLE / sizeof TABLE[0];
    return TABLE;
}

bool MotionTranslator::translate(const NMLmsg &msg, MotionCommands &out, std::string *error)
{
    size_t n;
    const Entry *t = table(&n);
    for (size_t i = 0; i < n; i++) {
        if (t[i].type != msg.type) continue;
        Ctx c{*this, msg, out, error};
        return t[i].fn(c);
    }
    return false;
}
