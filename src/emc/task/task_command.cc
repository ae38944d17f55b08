// task_command.cc: which command is accepted in which situation (nml.md sec. 4 table) and what each one does.
#include "task.hh"

#include <cstdio>

namespace {

// Command families of the acceptance table.
enum Family : unsigned {
    OPER = 1u << 0, CFG = 1u << 1, COMP = 1u << 2, OVR = 1u << 3, TRJV = 1u << 4, TSK = 1u << 5,
    PLANM = 1u << 6, PF = 1u << 7, PR = 1u << 8, IO = 1u << 9, TELE = 1u << 10, TT = 1u << 11,
    TNUM = 1u << 12, OVLIM = 1u << 13, MINMAX = 1u << 14, HALT = 1u << 15, HOME = 1u << 16,
    JOG = 1u << 17, TRJ = 1u << 18, SP = 1u << 19, SPO = 1u << 20, COOL = 1u << 21,
    PPR = 1u << 22, EXEC = 1u << 23, RUN = 1u << 24, STEP = 1u << 25, SPADJ = 1u << 26,
};

const unsigned NOT_ON = OPER | CFG | COMP | OVR | TRJV | TSK | PLANM | PF | PR | IO | TELE | TT | TNUM | OVLIM;
const unsigned MANUAL = OPER | CFG | MINMAX | HALT | HOME | JOG | TELE | OVLIM | TRJ | OVR | SP | SPADJ |
                        COOL | TSK | PLANM | PPR | PF | PR | IO | TT | TNUM | EXEC | RUN;
const unsigned MDI = OPER | CFG | OVR | SP | SPADJ | SPO | COOL | TSK | PLANM | PPR | PF | PR | IO | TT |
                     JOG | TELE | EXEC;
const unsigned AUTO_IDLE = OPER | CFG | TRJ | OVR | SP | SPADJ | SPO | COOL | TSK | PLANM | RUN | EXEC |
                           PPR | PF | PR | TT | JOG | TELE | STEP;
const unsigned AUTO_READING = OPER | CFG | TRJ | OVR | SPADJ | PPR | PF | TSK | PR | COOL | STEP;
const unsigned AUTO_PAUSED = OPER | CFG | TRJ | OVR | SP | SPADJ | SPO | COOL | TSK | EXEC | PPR | PF | PR | STEP;
const unsigned AUTO_WAITING = AUTO_READING | EXEC;

struct Handler {
    NMLTYPE type;
    unsigned family;
    void (*run)(Task &t, const NMLmsg &msg);
};

template <class M>
const M &as(const NMLmsg &msg) { return *emc_msg_as<M>(&msg); }

void op_error(Task &t, const NMLmsg &m) { t.operator_message(m.type, as<EMC_OPERATOR_ERROR>(m).error); }
void op_text(Task &t, const NMLmsg &m) { t.operator_message(m.type, as<EMC_OPERATOR_TEXT>(m).text); }
void op_display(Task &t, const NMLmsg &m) { t.operator_message(m.type, as<EMC_OPERATOR_DISPLAY>(m).display); }
void motion(Task &t, const NMLmsg &m)
{
    if (t.check_io_index(m)) t.issue_motion(m);
}
void nothing(Task &, const NMLmsg &) {}
void set_debug(Task &t, const NMLmsg &m) { t.set_debug(as<EMC_SET_DEBUG>(m).debug); }
void set_state(Task &t, const NMLmsg &m) { t.set_state(as<EMC_TASK_SET_STATE>(m).state); }
void set_mode(Task &t, const NMLmsg &m) { t.set_mode(as<EMC_TASK_SET_MODE>(m).mode); }
void abort_cmd(Task &t, const NMLmsg &) { t.task_abort(); }
void override_limits(Task &t, const NMLmsg &m)
{
    if (t.task_mode() == EMC_TASK_MODE_MANUAL) t.issue_motion(m);
}
void plan_open(Task &t, const NMLmsg &m) { t.plan_open_msg(as<EMC_TASK_PLAN_OPEN>(m)); }
void plan_close(Task &t, const NMLmsg &) { t.plan_close(); }
void plan_init(Task &t, const NMLmsg &) { t.plan_init(); }
void plan_synch(Task &t, const NMLmsg &) { t.plan_synch(); }
void plan_run(Task &t, const NMLmsg &m) { t.plan_run(as<EMC_TASK_PLAN_RUN>(m).line); }
void plan_execute(Task &t, const NMLmsg &m) { t.plan_execute(as<EMC_TASK_PLAN_EXECUTE>(m).command); }
void plan_pause(Task &t, const NMLmsg &) { t.plan_pause(); }
void plan_resume(Task &t, const NMLmsg &) { t.plan_resume(); }
void plan_step(Task &t, const NMLmsg &) { t.plan_step(); }
void optional_stop(Task &t, const NMLmsg &m) { t.set_optional_stop(as<EMC_TASK_PLAN_SET_OPTIONAL_STOP>(m).state); }
void block_delete(Task &t, const NMLmsg &m) { t.set_block_delete(as<EMC_TASK_PLAN_SET_BLOCK_DELETE>(m).state); }
void m1_stop(Task &t, const NMLmsg &)
{
    if (t.stat().task.optional_stop_state) t.plan_pause();
}
void load_table(Task &t, const NMLmsg &m) { t.tool_load_table(as<EMC_TOOL_LOAD_TOOL_TABLE>(m).file); }
void tool_offset(Task &t, const NMLmsg &m) { t.tool_set_offset(as<EMC_TOOL_SET_OFFSET>(m)); }
void tool_number(Task &t, const NMLmsg &m) { t.tool_set_number(as<EMC_TOOL_SET_NUMBER>(m).tool); }
void mist_on(Task &t, const NMLmsg &) { t.coolant(true, true); }
void mist_off(Task &t, const NMLmsg &) { t.coolant(true, false); }
void flood_on(Task &t, const NMLmsg &) { t.coolant(false, true); }
void flood_off(Task &t, const NMLmsg &) { t.coolant(false, false); }
void spindle_speed(Task &t, const NMLmsg &m) { t.spindle_speed(as<EMC_SPINDLE_SPEED>(m)); }

const Handler HANDLERS[] = {
    {EMC_OPERATOR_ERROR_TYPE, OPER, op_error},
    {EMC_OPERATOR_TEXT_TYPE, OPER, op_text},
    {EMC_OPERATOR_DISPLAY_TYPE, OPER, op_display},
    {EMC_SET_DEBUG_TYPE, TSK, set_debug},
    {EMC_TASK_SET_MODE_TYPE, TSK, set_mode},
    {EMC_TASK_SET_STATE_TYPE, TSK, set_state},
    {EMC_TASK_ABORT_TYPE, TSK, abort_cmd},
    {EMC_JOINT_SET_BACKLASH_TYPE, CFG, motion},
    {EMC_JOINT_SET_HOMING_PARAMS_TYPE, CFG, motion},
    {EMC_JOINT_SET_FERROR_TYPE, CFG, motion},
    {EMC_JOINT_SET_MIN_FERROR_TYPE, CFG, motion},
    {EMC_JOINT_UNHOME_TYPE, CFG, motion},
    {EMC_JOINT_LOAD_COMP_TYPE, COMP, motion},
    {EMC_JOINT_SET_MIN_POSITION_LIMIT_TYPE, MINMAX, motion},
    {EMC_JOINT_SET_MAX_POSITION_LIMIT_TYPE, MINMAX, motion},
    {EMC_JOINT_HALT_TYPE, HALT, motion},
    {EMC_JOINT_HOME_TYPE, HOME, motion},
    {EMC_JOINT_OVERRIDE_LIMITS_TYPE, OVLIM, override_limits},
    {EMC_JOG_CONT_TYPE, JOG, motion},
    {EMC_JOG_INCR_TYPE, JOG, motion},
    {EMC_JOG_ABS_TYPE, JOG, motion},
    {EMC_JOG_STOP_TYPE, JOG, motion},
    {EMC_TRAJ_SET_TELEOP_ENABLE_TYPE, TELE, motion},
    {EMC_TRAJ_PAUSE_TYPE, TRJ, motion},
    {EMC_TRAJ_RESUME_TYPE, TRJ, motion},
    {EMC_TRAJ_ABORT_TYPE, TRJ, motion},
    {EMC_TRAJ_SET_SCALE_TYPE, OVR, motion},
    {EMC_TRAJ_SET_RAPID_SCALE_TYPE, OVR, motion},
    {EMC_TRAJ_SET_MAX_VELOCITY_TYPE, OVR, motion},
    {EMC_TRAJ_SET_SPINDLE_SCALE_TYPE, OVR, motion},
    {EMC_TRAJ_SET_FO_ENABLE_TYPE, OVR, motion},
    {EMC_TRAJ_SET_FH_ENABLE_TYPE, OVR, motion},
    {EMC_TRAJ_SET_SO_ENABLE_TYPE, OVR, motion},
    {EMC_TRAJ_SET_VELOCITY_TYPE, TRJV, motion},
    {EMC_TRAJ_SET_ACCELERATION_TYPE, TRJV, motion},
    {EMC_SPINDLE_ON_TYPE, SP, motion},
    {EMC_SPINDLE_OFF_TYPE, SP, motion},
    {EMC_SPINDLE_SPEED_TYPE, SP, spindle_speed},
    {EMC_SPINDLE_BRAKE_RELEASE_TYPE, SP, motion},
    {EMC_SPINDLE_BRAKE_ENGAGE_TYPE, SP, motion},
    {EMC_SPINDLE_INCREASE_TYPE, SPADJ, motion},
    {EMC_SPINDLE_DECREASE_TYPE, SPADJ, motion},
    {EMC_SPINDLE_CONSTANT_TYPE, SPADJ, motion},
    {EMC_SPINDLE_ORIENT_TYPE, SPO, motion},
    {EMC_SPINDLE_WAIT_ORIENT_COMPLETE_TYPE, SPO, nothing},
    {EMC_COOLANT_MIST_ON_TYPE, COOL, mist_on},
    {EMC_COOLANT_MIST_OFF_TYPE, COOL, mist_off},
    {EMC_COOLANT_FLOOD_ON_TYPE, COOL, flood_on},
    {EMC_COOLANT_FLOOD_OFF_TYPE, COOL, flood_off},
    {EMC_TASK_PLAN_OPEN_TYPE, PLANM, plan_open},
    {EMC_TASK_PLAN_CLOSE_TYPE, PLANM, plan_close},
    {EMC_TASK_PLAN_INIT_TYPE, PLANM, plan_init},
    {EMC_TASK_PLAN_SYNCH_TYPE, PLANM, plan_synch},
    {EMC_TASK_PLAN_RUN_TYPE, RUN, plan_run},
    {EMC_TASK_PLAN_EXECUTE_TYPE, EXEC, plan_execute},
    {EMC_TASK_PLAN_STEP_TYPE, STEP, plan_step},
    {EMC_TASK_PLAN_PAUSE_TYPE, PPR, plan_pause},
    {EMC_TASK_PLAN_RESUME_TYPE, PPR, plan_resume},
    {EMC_TASK_PLAN_REVERSE_TYPE, PPR, motion},
    {EMC_TASK_PLAN_FORWARD_TYPE, PPR, motion},
    {EMC_TASK_PLAN_SET_OPTIONAL_STOP_TYPE, PF, optional_stop},
    {EMC_TASK_PLAN_SET_BLOCK_DELETE_TYPE, PF, block_delete},
    {EMC_TASK_PLAN_OPTIONAL_STOP_TYPE, PF, m1_stop},
    {EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG_TYPE, PR, motion},
    {EMC_TRAJ_PROBE_TYPE, PR, motion},
    {EMC_TRAJ_RIGID_TAP_TYPE, PR, motion},
    {EMC_AUX_INPUT_WAIT_TYPE, PR, nothing},
    {EMC_MOTION_SET_DOUT_TYPE, IO, motion},
    {EMC_MOTION_SET_AOUT_TYPE, IO, motion},
    {EMC_MOTION_ADAPTIVE_TYPE, IO, motion},
    {EMC_TOOL_LOAD_TOOL_TABLE_TYPE, TT, load_table},
    {EMC_TOOL_SET_OFFSET_TYPE, TT, tool_offset},
    {EMC_TOOL_SET_NUMBER_TYPE, TNUM, tool_number},
};

const Handler *find_handler(NMLTYPE type)
{
    for (const Handler &h : HANDLERS)
        if (h.type == type) return &h;
    return nullptr;
}

}  // namespace

// Families allowed now, and the rejection text for the others.
static unsigned allowed(const Task &t, int interp, std::string &fmt)
{
    if (t.task_state() != EMC_TASK_STATE_ON) {
        fmt = "command (%s) cannot be executed until the machine is out of E-stop and turned on";
        return NOT_ON;
    }
    switch (t.task_mode()) {
    case EMC_TASK_MODE_MANUAL:
        fmt = "can't do that (%s:%d) in manual mode";
        return MANUAL;
    case EMC_TASK_MODE_MDI:
        fmt = "can't do that (%s:%d) in MDI mode";
        return MDI;
    default:
        break;
    }
    switch (interp) {
    case EMC_TASK_INTERP_READING: fmt = "can't do that (%s) in auto mode with the interpreter reading"; return AUTO_READING;
    case EMC_TASK_INTERP_PAUSED: fmt = "can't do that (%s) in auto mode with the interpreter paused"; return AUTO_PAUSED;
    case EMC_TASK_INTERP_WAITING: fmt = "can't do that (%s) in auto mode with the interpreter waiting"; return AUTO_WAITING;
    default: fmt = "can't do that (%s) in auto mode with the interpreter idle"; return AUTO_IDLE;
    }
}

// Spindle numbers and motion I/O indexes outside the configuration are refused before motion
// sees them (LinuxCNC's texts: a spindle is a failed command, an I/O index only an error).
bool Task::check_io_index(const NMLmsg &msg)
{
    int spindle = -1;
    if (msg.type >= EMC_SPINDLE_ON_TYPE && msg.type <= EMC_SPINDLE_WAIT_ORIENT_COMPLETE_TYPE)
        spindle = static_cast<const EMC_SPINDLE_CMD_MSG &>(msg).spindle;
    if (spindle >= cfg_.spindles || spindle < -1) {
        reject("Attempt to start non-existent spindle");
        return false;
    }
    int index = -1, limit = 0;
    const char *what = "";
    if (auto *d = emc_msg_as<EMC_MOTION_SET_DOUT>(&msg)) { index = d->index; limit = mst_.num_dio; what = "num_dio/EMCMOT_MAX_DIO"; }
    if (auto *a = emc_msg_as<EMC_MOTION_SET_AOUT>(&msg)) { index = a->index; limit = mst_.num_aio; what = "num_aio/EMCMOT_MAX_AIO"; }
    if (index >= 0 && index >= limit) {
        char text[LINELEN];
        snprintf(text, sizeof text, "ERROR: index out of range, %d not in [0..%d] (increase %s=%d)\n", index, limit,
                 what, EMCMOT_MAX_DIO);
        operator_error(text);
        return false;
    }
    return true;
}

// A new command from emcCommand: accept (run its handler) or reject with LinuxCNC's text.
void Task::handle_command(const NMLmsg &msg)
{
    command_failed_ = false;
    exec_error_ = false;
    const Handler *h = find_handler(msg.type);
    std::string fmt;
    unsigned ok = allowed(*this, interp_state_, fmt);
    if (h && (h->family & ok)) {
        h->run(*this, msg);
        return;
    }
    char text[LINELEN];
    snprintf(text, sizeof text, fmt.c_str(), emc_symbol_lookup(msg.type), (int)msg.type);
    reject(text);
}
