// responder_commands.cc: which commands task accepts in which state (nml.md sec. 4) and what each one does to the simulation.
#include <cmath>
#include <cstdio>
#include <fstream>

#include "responder.hh"

namespace {

// Command families of the acceptance table.
enum Family : unsigned {
    OPER = 1u << 0, CFG = 1u << 1, COMP = 1u << 2, OVR = 1u << 3, TRJV = 1u << 4, TSK = 1u << 5,
    PLANM = 1u << 6, PF = 1u << 7, PR = 1u << 8, IO = 1u << 9, TELE = 1u << 10, TT = 1u << 11,
    TNUM = 1u << 12, OVLIM = 1u << 13, MINMAX = 1u << 14, HALT = 1u << 15, HOME = 1u << 16,
    JOG = 1u << 17, TRJ = 1u << 18, SP = 1u << 19, SPO = 1u << 20, COOL = 1u << 21,
    PPR = 1u << 22, EXEC = 1u << 23, RUN = 1u << 24, STEP = 1u << 25,
};

const unsigned NOT_ON = OPER | CFG | COMP | OVR | TRJV | TSK | PLANM | PF | PR | IO | TELE | TT | TNUM | OVLIM;
const unsigned MANUAL = OPER | CFG | MINMAX | HALT | HOME | JOG | TELE | OVLIM | TRJ | OVR | SP | COOL |
                        TSK | PLANM | PPR | PF | PR | IO | TT | TNUM | EXEC | RUN;
const unsigned MDI = OPER | CFG | OVR | SP | SPO | COOL | TSK | PLANM | PPR | PF | PR | IO | TT | JOG |
                     TELE | EXEC;
const unsigned AUTO_IDLE = OPER | CFG | TRJ | OVR | SP | SPO | COOL | TSK | PLANM | RUN | EXEC | PPR |
                           PF | PR | TT | JOG | TELE | STEP;
const unsigned AUTO_READING = OPER | CFG | TRJ | OVR | PPR | PF | TSK | PR | COOL | STEP;
const unsigned AUTO_PAUSED = OPER | CFG | TRJ | OVR | SP | SPO | COOL | TSK | EXEC | PPR | PF | PR | STEP;

// One handled type: its family and what it does.
struct Handler {
    NMLTYPE type;
    unsigned family;
    void (*run)(Machine &m, const NMLmsg &msg);
};

// The typed message (the channel already checked type and size).
template <class M>
const M &as(const NMLmsg &msg)
{
    return *emc_msg_as<M>(&msg);
}

// Reject the current command with an error text: RCS_ERROR until the next command.
void reject(Machine &m, const std::string &text)
{
    if (!text.empty()) responder_error(m, text);
    m.rejected = true;
}

void op_error(Machine &m, const NMLmsg &msg) { emc_send_operator_message(*m.err, msg.type, as<EMC_OPERATOR_ERROR>(msg).error); }
void op_text(Machine &m, const NMLmsg &msg) { emc_send_operator_message(*m.err, msg.type, as<EMC_OPERATOR_TEXT>(msg).text); }
void op_display(Machine &m, const NMLmsg &msg) { emc_send_operator_message(*m.err, msg.type, as<EMC_OPERATOR_DISPLAY>(msg).display); }
void set_debug(Machine &m, const NMLmsg &msg) { m.status.debug = as<EMC_SET_DEBUG>(msg).debug; }
void abort_cmd(Machine &m, const NMLmsg &) { responder_abort(m); }

// Leaving ON (or going to E-stop) aborts everything.
void set_state(Machine &m, const NMLmsg &msg)
{
    switch (as<EMC_TASK_SET_STATE>(msg).state) {
    case EMC_TASK_STATE_ESTOP: m.estop = true; m.enabled = false; responder_abort(m); break;
    case EMC_TASK_STATE_ESTOP_RESET: m.estop = false; responder_abort(m); break;
    case EMC_TASK_STATE_ON: if (!m.estop) m.enabled = true; break;
    case EMC_TASK_STATE_OFF: m.enabled = false; responder_abort(m); break;
    default: break;
    }
}

void set_mode(Machine &m, const NMLmsg &msg)
{
    int mode = as<EMC_TASK_SET_MODE>(msg).mode;
    if (responder_task_mode(m) == EMC_TASK_MODE_AUTO && m.interp != EMC_TASK_INTERP_IDLE &&
        mode != EMC_TASK_MODE_AUTO) {
        responder_error(m, "Can't switch mode while mode is AUTO and interpreter is not IDLE");
        return;
    }
    if (mode != responder_task_mode(m)) responder_abort(m);
    m.requested_mode = mode;
    if (mode == EMC_TASK_MODE_MANUAL)
        m.traj_mode = responder_all_homed(m) ? EMC_TRAJ_MODE_TELEOP : EMC_TRAJ_MODE_FREE;
    else
        m.traj_mode = EMC_TRAJ_MODE_COORD;
}

// MDI: guards, then run at once or queue behind the running one.
void plan_execute(Machine &m, const NMLmsg &msg)
{
    if (!responder_all_homed(m) && !m.cfg.no_force_homing)
        return reject(m, "Can't issue MDI command when not homed");
    if (responder_task_mode(m) != EMC_TASK_MODE_MDI)
        return reject(m, "Must be in MDI mode to issue MDI command");
    m.mdi_queue.push_back(as<EMC_TASK_PLAN_EXECUTE>(msg).command);
}

void plan_open(Machine &m, const NMLmsg &msg)
{
    std::string file = as<EMC_TASK_PLAN_OPEN>(msg).file;
    std::ifstream in(file);
    if (!in) {
        responder_error(m, "Unable to open file <" + file + ">");
        return reject(m, "can't open " + file);
    }
    std::string line;
    m.program_lines = 0;
    while (std::getline(in, line)) m.program_lines++;
    m.program = file;
    emc_set_text(m.status.task.file, file.c_str());
}

void plan_run(Machine &m, const NMLmsg &msg)
{
    if (responder_task_mode(m) != EMC_TASK_MODE_AUTO) return; // MANUAL: ignored, no error
    if (!responder_all_homed(m) && !m.cfg.no_force_homing)
        return reject(m, "Can't run a program when not homed");
    int start = as<EMC_TASK_PLAN_RUN>(msg).line;
    if (m.program.empty() || start < 0 || start > m.program_lines) return;
    m.interp = EMC_TASK_INTERP_READING;
    m.program_line = start > 0 ? start : 1;
    m.next_line_at = m.now;
}

void plan_pause(Machine &m, const NMLmsg &) { if (m.interp != EMC_TASK_INTERP_IDLE) m.paused = true; }
void plan_resume(Machine &m, const NMLmsg &) { m.paused = false; }
void plan_close(Machine &m, const NMLmsg &) { m.program.clear(); }

// STEP: in AUTO with the interpreter idle the program starts paused (single-step mode);
// otherwise the paused program goes on.
void plan_step(Machine &m, const NMLmsg &)
{
    if (m.interp != EMC_TASK_INTERP_IDLE || m.program.empty()) {
        m.paused = false;
        return;
    }
    m.interp = EMC_TASK_INTERP_READING;
    m.program_line = 1;
    m.next_line_at = m.now;
    m.paused = true;
}
void optional_stop(Machine &m, const NMLmsg &msg) { m.status.task.optional_stop_state = as<EMC_TASK_PLAN_SET_OPTIONAL_STOP>(msg).state != 0; }
void block_delete(Machine &m, const NMLmsg &msg) { m.status.task.block_delete_state = as<EMC_TASK_PLAN_SET_BLOCK_DELETE>(msg).state != 0; }

void joint_home(Machine &m, const NMLmsg &msg)
{
    int j = as<EMC_JOINT_HOME>(msg).joint;
    if (m.traj_mode != EMC_TRAJ_MODE_FREE) return responder_error(m, "must be in joint mode to home");
    for (int i = 0; i < m.cfg.joints; i++)
        if (j == -1 || j == i) m.home_done_at[i] = m.now + 0.2;
}

void joint_unhome(Machine &m, const NMLmsg &msg)
{
    int j = as<EMC_JOINT_UNHOME>(msg).joint;
    if (m.traj_mode == EMC_TRAJ_MODE_TELEOP && m.enabled)
        return responder_error(m, "must be in joint mode or disabled to unhome");
    for (int i = 0; i < m.cfg.joints; i++)
        if (j == -1 || j == i) m.homed[i] = false;
}

void teleop_enable(Machine &m, const NMLmsg &msg)
{
    m.traj_mode = as<EMC_TRAJ_SET_TELEOP_ENABLE>(msg).enable ? EMC_TRAJ_MODE_TELEOP : EMC_TRAJ_MODE_FREE;
}

// Jogs: axis jogs need TELEOP, joint jogs FREE (the errors are motion's).
bool jog_allowed(Machine &m, const EMC_JOG_CMD_MSG &j, const char *name)
{
    if (j.jjogmode == EMC_JOG_JOINT && m.traj_mode == EMC_TRAJ_MODE_TELEOP) {
        responder_error(m, std::string(name) + " Mode is TELEOP, cannot jog joint\n");
        return false;
    }
    if (j.jjogmode == EMC_JOG_AXIS && m.traj_mode != EMC_TRAJ_MODE_TELEOP) {
        responder_error(m, "Joint jog requested for undefined joint number=-1 (min=0,max=" +
                               std::to_string(m.cfg.joints - 1) + ")");
        return false;
    }
    int limit = j.jjogmode == EMC_JOG_JOINT ? m.cfg.joints : 9;
    return j.joint_or_axis >= 0 && j.joint_or_axis < limit &&
           (j.jjogmode == EMC_JOG_JOINT || (m.cfg.axis_mask >> j.joint_or_axis) & 1);
}

// Clamp a jog velocity to the maximum.
double clamp_vel(const Machine &m, double v)
{
    return v > m.cfg.max_velocity ? m.cfg.max_velocity : v < -m.cfg.max_velocity ? -m.cfg.max_velocity : v;
}

void jog_cont(Machine &m, const NMLmsg &msg)
{
    const EMC_JOG_CONT &j = as<EMC_JOG_CONT>(msg);
    if (!jog_allowed(m, j, "JOG_CONT")) return;
    int i = j.joint_or_axis;
    if (j.jjogmode == EMC_JOG_JOINT) m.joint_jog_vel[i] = clamp_vel(m, j.vel);
    else { m.jog_vel[i] = clamp_vel(m, j.vel); m.jog_to_target[i] = false; }
}

void jog_incr(Machine &m, const NMLmsg &msg)
{
    const EMC_JOG_INCR &j = as<EMC_JOG_INCR>(msg);
    if (!jog_allowed(m, j, "JOG_INCR") || j.jjogmode == EMC_JOG_JOINT) return;
    int i = j.joint_or_axis;
    // As motion does: the sign of vel is the direction, incr is added or taken away.
    double step = j.vel > 0 ? j.incr : -j.incr;
    m.jog_target[i] = m.pos[i] + step;
    m.jog_vel[i] = clamp_vel(m, step < 0 ? -std::abs(j.vel) : std::abs(j.vel));
    m.jog_to_target[i] = true;
}

void jog_stop(Machine &m, const NMLmsg &msg)
{
    const EMC_JOG_STOP &j = as<EMC_JOG_STOP>(msg);
    if (j.joint_or_axis < 0 || j.joint_or_axis >= 9) return;
    if (j.jjogmode == EMC_JOG_JOINT && j.joint_or_axis < EMCMOT_MAX_JOINTS) m.joint_jog_vel[j.joint_or_axis] = 0;
    else m.jog_vel[j.joint_or_axis] = 0;
}

void feed_scale(Machine &m, const NMLmsg &msg) { m.status.motion.traj.scale = as<EMC_TRAJ_SET_SCALE>(msg).scale; }
void rapid_scale(Machine &m, const NMLmsg &msg) { m.status.motion.traj.rapid_scale = as<EMC_TRAJ_SET_RAPID_SCALE>(msg).scale; }
void max_vel(Machine &m, const NMLmsg &msg) { m.status.motion.traj.maxVelocity = as<EMC_TRAJ_SET_MAX_VELOCITY>(msg).velocity; }
void fo_enable(Machine &m, const NMLmsg &msg) { m.status.motion.traj.feed_override_enabled = as<EMC_TRAJ_SET_FO_ENABLE>(msg).mode != 0; }
void fh_enable(Machine &m, const NMLmsg &msg) { m.status.motion.traj.feed_hold_enabled = as<EMC_TRAJ_SET_FH_ENABLE>(msg).mode != 0; }
void adaptive(Machine &m, const NMLmsg &msg) { m.status.motion.traj.adaptive_feed_enabled = as<EMC_MOTION_ADAPTIVE>(msg).status != 0; }
void flood_on(Machine &m, const NMLmsg &) { m.status.io.coolant.flood = 1; }
void flood_off(Machine &m, const NMLmsg &) { m.status.io.coolant.flood = 0; }
void mist_on(Machine &m, const NMLmsg &) { m.status.io.coolant.mist = 1; }
void mist_off(Machine &m, const NMLmsg &) { m.status.io.coolant.mist = 0; }

// The spindle a command names, or nullptr (spindle commands to others are ignored).
EMC_SPINDLE_STAT *spindle_of(Machine &m, int spindle)
{
    return spindle >= 0 && spindle < m.cfg.spindles ? &m.status.motion.spindle[spindle] : nullptr;
}

void so_enable(Machine &m, const NMLmsg &msg)
{
    const EMC_TRAJ_SET_SO_ENABLE &c = as<EMC_TRAJ_SET_SO_ENABLE>(msg);
    if (EMC_SPINDLE_STAT *s = spindle_of(m, c.spindle)) s->spindle_override_enabled = c.mode != 0;
}

void spindle_scale(Machine &m, const NMLmsg &msg)
{
    const EMC_TRAJ_SET_SPINDLE_SCALE &c = as<EMC_TRAJ_SET_SPINDLE_SCALE>(msg);
    if (EMC_SPINDLE_STAT *s = spindle_of(m, c.spindle)) s->spindle_scale = c.scale;
}

void spindle_on(Machine &m, const NMLmsg &msg)
{
    const EMC_SPINDLE_ON &c = as<EMC_SPINDLE_ON>(msg);
    EMC_SPINDLE_STAT *s = spindle_of(m, c.spindle);
    if (!s) return reject(m, "Attempt to start non-existent spindle");
    s->speed = c.speed;
    s->direction = c.speed > 0 ? 1 : c.speed < 0 ? -1 : 0;
    s->enabled = c.speed != 0;
    s->brake = c.speed == 0;
}

void spindle_off(Machine &m, const NMLmsg &msg)
{
    if (EMC_SPINDLE_STAT *s = spindle_of(m, as<EMC_SPINDLE_OFF>(msg).spindle)) {
        s->speed = 0;
        s->direction = 0;
        s->enabled = 0;
        s->brake = 1;
    }
}

// INCREASE/DECREASE: 100 rpm away from / towards zero while running.
void spindle_step(Machine &m, int spindle, double step)
{
    EMC_SPINDLE_STAT *s = spindle_of(m, spindle);
    if (!s || s->direction == 0) return;
    double mag = std::abs(s->speed) + step;
    s->speed = s->direction * (mag < 0 ? 0 : mag);
}

void spindle_increase(Machine &m, const NMLmsg &msg) { spindle_step(m, as<EMC_SPINDLE_INCREASE>(msg).spindle, 100); }
void spindle_decrease(Machine &m, const NMLmsg &msg) { spindle_step(m, as<EMC_SPINDLE_DECREASE>(msg).spindle, -100); }
void brake_engage(Machine &m, const NMLmsg &msg) { if (auto *s = spindle_of(m, as<EMC_SPINDLE_BRAKE_ENGAGE>(msg).spindle)) s->brake = 1; }
void brake_release(Machine &m, const NMLmsg &msg) { if (auto *s = spindle_of(m, as<EMC_SPINDLE_BRAKE_RELEASE>(msg).spindle)) s->brake = 0; }

// Motion I/O index check (motion reports it; not a task rejection).
bool io_index_ok(Machine &m, int index, int count)
{
    if (index < count) return true;
    responder_error(m, "ERROR: index out of range, " + std::to_string(index) + " not in [0.." +
                           std::to_string(count) + "] (increase num_dio/EMCMOT_MAX_DIO=64)\n");
    return false;
}

void set_dout(Machine &m, const NMLmsg &msg)
{
    const EMC_MOTION_SET_DOUT &c = as<EMC_MOTION_SET_DOUT>(msg);
    if (io_index_ok(m, c.index, m.cfg.num_dio)) m.status.motion.synch_do[c.index] = c.start != 0;
}

void set_aout(Machine &m, const NMLmsg &msg)
{
    const EMC_MOTION_SET_AOUT &c = as<EMC_MOTION_SET_AOUT>(msg);
    if (io_index_ok(m, c.index, m.cfg.num_aio)) m.status.motion.analog_output[c.index] = c.start;
}

void min_limit(Machine &m, const NMLmsg &msg)
{
    const EMC_JOINT_SET_MIN_POSITION_LIMIT &c = as<EMC_JOINT_SET_MIN_POSITION_LIMIT>(msg);
    if (c.joint >= 0 && c.joint < m.cfg.joints) m.status.motion.joint[c.joint].minPositionLimit = c.limit;
}

void max_limit(Machine &m, const NMLmsg &msg)
{
    const EMC_JOINT_SET_MAX_POSITION_LIMIT &c = as<EMC_JOINT_SET_MAX_POSITION_LIMIT>(msg);
    if (c.joint >= 0 && c.joint < m.cfg.joints) m.status.motion.joint[c.joint].maxPositionLimit = c.limit;
}

// M61: the tool in the spindle; entry 0 of the tool data follows it.
void tool_set_number(Machine &m, const NMLmsg &msg)
{
    int tool = as<EMC_TOOL_SET_NUMBER>(msg).tool;
    m.status.io.tool.toolInSpindle = tool;
    m.tool_table[0] = tooldata_empty_entry();
    for (size_t i = 1; i < m.tool_table.size(); i++)
        if (m.tool_table[i].toolno == tool) m.tool_table[0] = m.tool_table[i];
    if (tool == 0) m.tool_table[0].toolno = 0;
    m.status.io.tool.toolTableCurrent = m.tool_table[0];
    responder_publish_tools(m);
}

// G10 L1 / tool_offset(): update the row of the tool (the one named, else found by number).
void tool_set_offset(Machine &m, const NMLmsg &msg)
{
    const EMC_TOOL_SET_OFFSET &c = as<EMC_TOOL_SET_OFFSET>(msg);
    size_t row = c.pocket > 0 ? static_cast<size_t>(c.pocket) : 0;
    for (size_t i = 1; row == 0 && i < m.tool_table.size(); i++)
        if (m.tool_table[i].toolno == c.toolno) row = i;
    if (row == 0 || row >= m.tool_table.size()) {
        row = m.tool_table.size();
        m.tool_table.push_back(tooldata_empty_entry());
    }
    tooldata_entry_t &e = m.tool_table[row];
    e.toolno = c.toolno;
    e.offset = c.offset;
    e.diameter = c.diameter;
    e.frontangle = c.frontangle;
    e.backangle = c.backangle;
    e.orientation = c.orientation;
    responder_publish_tools(m);
}

void load_tool_table(Machine &m, const NMLmsg &)
{
    if (!m.cfg.tool_table.empty()) responder_load_tools(m, m.cfg.tool_table);
}

const Handler handlers[] = {
    {EMC_OPERATOR_ERROR_TYPE, OPER, op_error},
    {EMC_OPERATOR_TEXT_TYPE, OPER, op_text},
    {EMC_OPERATOR_DISPLAY_TYPE, OPER, op_display},
    {EMC_SET_DEBUG_TYPE, TSK, set_debug},
    {EMC_TASK_ABORT_TYPE, TSK, abort_cmd},
    {EMC_TASK_SET_MODE_TYPE, TSK, set_mode},
    {EMC_TASK_SET_STATE_TYPE, TSK, set_state},
    {EMC_TASK_PLAN_EXECUTE_TYPE, EXEC, plan_execute},
    {EMC_TASK_PLAN_OPEN_TYPE, PLANM, plan_open},
    {EMC_TASK_PLAN_CLOSE_TYPE, PLANM, plan_close},
    {EMC_TASK_PLAN_INIT_TYPE, PLANM, nullptr},
    {EMC_TASK_PLAN_SYNCH_TYPE, PLANM, nullptr},
    {EMC_TASK_PLAN_RUN_TYPE, RUN, plan_run},
    {EMC_TASK_PLAN_PAUSE_TYPE, PPR, plan_pause},
    {EMC_TASK_PLAN_RESUME_TYPE, PPR, plan_resume},
    {EMC_TASK_PLAN_REVERSE_TYPE, PPR, nullptr},
    {EMC_TASK_PLAN_FORWARD_TYPE, PPR, nullptr},
    {EMC_TASK_PLAN_STEP_TYPE, STEP, plan_step},
    {EMC_TASK_PLAN_SET_OPTIONAL_STOP_TYPE, PF, optional_stop},
    {EMC_TASK_PLAN_SET_BLOCK_DELETE_TYPE, PF, block_delete},
    {EMC_JOINT_HOME_TYPE, HOME, joint_home},
    {EMC_JOINT_UNHOME_TYPE, CFG, joint_unhome},
    {EMC_JOINT_SET_BACKLASH_TYPE, CFG, nullptr},
    {EMC_JOINT_SET_HOMING_PARAMS_TYPE, CFG, nullptr},
    {EMC_JOINT_SET_FERROR_TYPE, CFG, nullptr},
    {EMC_JOINT_SET_MIN_FERROR_TYPE, CFG, nullptr},
    {EMC_JOINT_LOAD_COMP_TYPE, COMP, nullptr},
    {EMC_JOINT_OVERRIDE_LIMITS_TYPE, OVLIM, nullptr},
    {EMC_JOINT_SET_MIN_POSITION_LIMIT_TYPE, MINMAX, min_limit},
    {EMC_JOINT_SET_MAX_POSITION_LIMIT_TYPE, MINMAX, max_limit},
    {EMC_JOINT_HALT_TYPE, HALT, nullptr},
    {EMC_JOG_CONT_TYPE, JOG, jog_cont},
    {EMC_JOG_INCR_TYPE, JOG, jog_incr},
    {EMC_JOG_STOP_TYPE, JOG, jog_stop},
    {EMC_JOG_ABS_TYPE, JOG, nullptr},
    {EMC_TRAJ_SET_TELEOP_ENABLE_TYPE, TELE, teleop_enable},
    {EMC_TRAJ_SET_SCALE_TYPE, OVR, feed_scale},
    {EMC_TRAJ_SET_RAPID_SCALE_TYPE, OVR, rapid_scale},
    {EMC_TRAJ_SET_MAX_VELOCITY_TYPE, OVR, max_vel},
    {EMC_TRAJ_SET_SPINDLE_SCALE_TYPE, OVR, spindle_scale},
    {EMC_TRAJ_SET_FO_ENABLE_TYPE, OVR, fo_enable},
    {EMC_TRAJ_SET_FH_ENABLE_TYPE, OVR, fh_enable},
    {EMC_TRAJ_SET_SO_ENABLE_TYPE, OVR, so_enable},
    {EMC_TRAJ_SET_VELOCITY_TYPE, TRJV, nullptr},
    {EMC_TRAJ_SET_ACCELERATION_TYPE, TRJV, nullptr},
    {EMC_TRAJ_PAUSE_TYPE, TRJ, nullptr},
    {EMC_TRAJ_RESUME_TYPE, TRJ, nullptr},
    {EMC_TRAJ_ABORT_TYPE, TRJ, nullptr},
    {EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG_TYPE, PR, nullptr},
    {EMC_MOTION_SET_DOUT_TYPE, IO, set_dout},
    {EMC_MOTION_SET_AOUT_TYPE, IO, set_aout},
    {EMC_MOTION_ADAPTIVE_TYPE, IO, adaptive},
    {EMC_SPINDLE_ON_TYPE, SP, spindle_on},
    {EMC_SPINDLE_OFF_TYPE, SP, spindle_off},
    {EMC_SPINDLE_INCREASE_TYPE, SP, spindle_increase},
    {EMC_SPINDLE_DECREASE_TYPE, SP, spindle_decrease},
    {EMC_SPINDLE_CONSTANT_TYPE, SP, nullptr},
    {EMC_SPINDLE_BRAKE_ENGAGE_TYPE, SP, brake_engage},
    {EMC_SPINDLE_BRAKE_RELEASE_TYPE, SP, brake_release},
    {EMC_SPINDLE_ORIENT_TYPE, SPO, nullptr},
    {EMC_COOLANT_FLOOD_ON_TYPE, COOL, flood_on},
    {EMC_COOLANT_FLOOD_OFF_TYPE, COOL, flood_off},
    {EMC_COOLANT_MIST_ON_TYPE, COOL, mist_on},
    {EMC_COOLANT_MIST_OFF_TYPE, COOL, mist_off},
    {EMC_TOOL_SET_NUMBER_TYPE, TNUM, tool_set_number},
    {EMC_TOOL_SET_OFFSET_TYPE, TT, tool_set_offset},
    {EMC_TOOL_LOAD_TOOL_TABLE_TYPE, TT, load_tool_table},
};

// Families task accepts now, and the wording of a refusal.
unsigned accepted_now(const Machine &m, std::string &where)
{
    static const char *const interp_names[] = {"", "idle", "reading", "paused", "waiting"};
    if (responder_task_state(m) != EMC_TASK_STATE_ON) return NOT_ON;
    int mode = responder_task_mode(m);
    if (mode == EMC_TASK_MODE_MANUAL) { where = "manual mode"; return MANUAL; }
    if (mode == EMC_TASK_MODE_MDI) { where = "MDI mode"; return MDI; }
    int interp = m.interp >= 1 && m.interp <= 4 ? m.interp : 1;
    where = std::string("auto mode with the interpreter ") + interp_names[interp];
    if (interp == EMC_TASK_INTERP_IDLE) return AUTO_IDLE;
    if (interp == EMC_TASK_INTERP_PAUSED) return AUTO_PAUSED;
    return interp == EMC_TASK_INTERP_WAITING ? (AUTO_READING | EXEC) : AUTO_READING;
}

// The refusal text of a command task does not take now.
std::string refusal(const Machine &m, NMLTYPE type, const std::string &where)
{
    const char *name = emc_symbol_lookup(type);
    if (responder_task_state(m) != EMC_TASK_STATE_ON)
        return std::string("command (") + name + ") cannot be executed until the machine is out of E-stop and turned on";
    if (responder_task_mode(m) == EMC_TASK_MODE_AUTO)
        return std::string("can't do that (") + name + ") in " + where;
    return std::string("can't do that (") + name + ":" + std::to_string(type) + ") in " + where;
}

} // namespace

// Handle one command: remember its serial, check acceptance, run its handler.
void responder_handle(Machine &m, const NMLmsg &msg)
{
    m.echo_serial = msg.serial_number;
    m.command_type = msg.type;
    m.rejected = false;
    const Handler *h = nullptr;
    for (const Handler &candidate : handlers)
        if (candidate.type == msg.type) h = &candidate;
    std::string where;
    unsigned ok = accepted_now(m, where);
    if (!h || !(h->family & ok)) return reject(m, refusal(m, msg.type, where));
    if (h->run) h->run(m, msg);
}
