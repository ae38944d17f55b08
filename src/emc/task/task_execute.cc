// task_execute.cc: issuing interp-list items in order, each when its precondition holds (LinuxCNC's execState).
#include "task.hh"

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

namespace {
const int ITEMS_PER_CYCLE = 500;

// What must be true before an item may be issued.
int precondition_of(NMLTYPE t)
{
    switch (t) {
    case EMC_TRAJ_LINEAR_MOVE_TYPE: case EMC_TRAJ_CIRCULAR_MOVE_TYPE: case EMC_TRAJ_PROBE_TYPE:
    case EMC_TRAJ_RIGID_TAP_TYPE:
        return EMC_TASK_EXEC_WAITING_FOR_MOTION_QUEUE;
    case EMC_TRAJ_SET_TERM_COND_TYPE: case EMC_TRAJ_SET_SPINDLESYNC_TYPE: case EMC_MOTION_SET_DOUT_TYPE:
    case EMC_MOTION_SET_AOUT_TYPE: case EMC_TRAJ_SET_FO_ENABLE_TYPE: case EMC_TRAJ_SET_SO_ENABLE_TYPE:
    case EMC_TRAJ_SET_FH_ENABLE_TYPE: case EMC_MOTION_ADAPTIVE_TYPE:
        return EMC_TASK_EXEC_DONE;
    default:
        return EMC_TASK_EXEC_WAITING_FOR_MOTION;
    }
}
}  // namespace

bool Task::precondition_met(const NMLmsg &msg)
{
    switch (precondition_of(msg.type)) {
    case EMC_TASK_EXEC_WAITING_FOR_MOTION_QUEUE:
        return motion_queue_room();
    case EMC_TASK_EXEC_WAITING_FOR_MOTION:
        return motion_done() && io_.done();
    default:
        return true;
    }
}

// The current wait finished?
bool Task::exec_waiting_done()
{
    switch (exec_state_) {
    case EMC_TASK_EXEC_WAITING_FOR_DELAY:
        st_.task.delayLeft = delay_until_ - now_ > 0 ? delay_until_ - now_ : 0;
        return now_ >= delay_until_;
    case EMC_TASK_EXEC_WAITING_FOR_MOTION: return motion_done();
    case EMC_TASK_EXEC_WAITING_FOR_MOTION_QUEUE: return motion_queue_room();
    case EMC_TASK_EXEC_WAITING_FOR_IO: return io_.done() && input_wait_done();
    case EMC_TASK_EXEC_WAITING_FOR_MOTION_AND_IO: return motion_done() && io_.done();
    case EMC_TASK_EXEC_WAITING_FOR_SYSTEM_CMD: {
        if (system_pid_ <= 0) return true;
        int status;
        if (waitpid(system_pid_, &status, WNOHANG) == 0) return false;
        system_pid_ = -1;
        return true;
    }
    case EMC_TASK_EXEC_WAITING_FOR_SPINDLE_ORIENTED: {
        const emcmot_spindle_status_t &s = mst_.spindle[orient_spindle_];
        if (s.orient_fault) {
            operator_error("fault " + std::to_string(s.orient_fault) + " during orient in progress");
            return true;
        }
        return s.orient_state != 1 || now_ >= orient_deadline_;
    }
    default:
        return true;
    }
}

// M66: the input reached the wanted state, or the timeout passed (then #5399 = -1).
bool Task::input_wait_done()
{
    // the inputs must come from a servo cycle that began after M66 was issued (two heartbeats:
    // the one running at issue time may have sampled them earlier)
    if (wait_input_fresh_ && mot_ && (int32_t)(mst_.heartbeat - wait_input_heartbeat_) < 2) return false;
    wait_input_fresh_ = false;
    if (wait_input_index_ < 0) return true;
    int idx = wait_input_index_;
    bool met = false;
    if (wait_input_digital_) {
        int v = mst_.synch_di[idx];
        switch (wait_input_type_) {
        case EMC_AUX_WAIT_RISE: met = v && !wait_input_start_; wait_input_start_ = v; break;
        case EMC_AUX_WAIT_FALL: met = !v && wait_input_start_; wait_input_start_ = v; break;
        case EMC_AUX_WAIT_HIGH: met = v != 0; break;
        case EMC_AUX_WAIT_LOW: met = v == 0; break;
        default: met = true; break;
        }
    } else {
        met = true;
    }
    if (met) {
        wait_input_index_ = -1;
        st_.task.input_timeout = 0;
        return true;
    }
    if (now_ >= wait_input_deadline_) {
        wait_input_index_ = -1;
        st_.task.input_timeout = 1;
        return true;
    }
    return false;
}

// One item: motion, io, task-internal; sets the exec state it leaves behind.
void Task::issue(const QueuedMsg &q)
{
    const NMLmsg &m = *q.msg();
    if (q.line > 0) current_line_ = q.line;
    exec_state_ = EMC_TASK_EXEC_DONE;
    switch (m.type) {
    case EMC_TRAJ_DELAY_TYPE:
        delay_until_ = now_ + emc_msg_as<EMC_TRAJ_DELAY>(&m)->delay;
        st_.task.delayLeft = emc_msg_as<EMC_TRAJ_DELAY>(&m)->delay;
        exec_state_ = EMC_TASK_EXEC_WAITING_FOR_DELAY;
        return;
    case EMC_TRAJ_SET_G5X_TYPE:
        st_.task.g5x_offset = emc_msg_as<EMC_TRAJ_SET_G5X>(&m)->origin;
        st_.task.g5x_index = emc_msg_as<EMC_TRAJ_SET_G5X>(&m)->g5x_index;
        return;
    case EMC_TRAJ_SET_G92_TYPE: st_.task.g92_offset = emc_msg_as<EMC_TRAJ_SET_G92>(&m)->origin; return;
    case EMC_TRAJ_SET_ROTATION_TYPE: st_.task.rotation_xy = emc_msg_as<EMC_TRAJ_SET_ROTATION>(&m)->rotation; return;
    case EMC_TRAJ_SET_OFFSET_TYPE:
        st_.task.toolOffset = emc_msg_as<EMC_TRAJ_SET_OFFSET>(&m)->offset;
        issue_motion(m);
        return;
    case EMC_TOOL_PREPARE_TYPE: {
        const auto *p = emc_msg_as<EMC_TOOL_PREPARE>(&m);
        io_.prepare(p->tool, p->pocket);
        exec_state_ = EMC_TASK_EXEC_WAITING_FOR_IO;
        return;
    }
    case EMC_TOOL_LOAD_TYPE:
        io_.load();
        exec_state_ = EMC_TASK_EXEC_WAITING_FOR_MOTION_AND_IO;
        return;
    case EMC_TOOL_SET_NUMBER_TYPE: tool_set_number(emc_msg_as<EMC_TOOL_SET_NUMBER>(&m)->tool); return;
    case EMC_TOOL_SET_OFFSET_TYPE: tool_set_offset(*emc_msg_as<EMC_TOOL_SET_OFFSET>(&m)); return;
    case EMC_TOOL_LOAD_TOOL_TABLE_TYPE: tool_load_table(emc_msg_as<EMC_TOOL_LOAD_TOOL_TABLE>(&m)->file); return;
    case EMC_COOLANT_MIST_ON_TYPE: io_.coolant(true, true); return;
    case EMC_COOLANT_MIST_OFF_TYPE: io_.coolant(true, false); return;
    case EMC_COOLANT_FLOOD_ON_TYPE: io_.coolant(false, true); return;
    case EMC_COOLANT_FLOOD_OFF_TYPE: io_.coolant(false, false); return;
    case EMC_SPINDLE_SPEED_TYPE: spindle_speed(*emc_msg_as<EMC_SPINDLE_SPEED>(&m)); return;
    case EMC_AUX_INPUT_WAIT_TYPE: start_input_wait(*emc_msg_as<EMC_AUX_INPUT_WAIT>(&m)); return;
    case EMC_SPINDLE_WAIT_ORIENT_COMPLETE_TYPE: {
        const auto *w = emc_msg_as<EMC_SPINDLE_WAIT_ORIENT_COMPLETE>(&m);
        orient_spindle_ = w->spindle >= 0 && w->spindle < EMCMOT_MAX_SPINDLES ? w->spindle : 0;
        orient_deadline_ = now_ + w->timeout;
        exec_state_ = EMC_TASK_EXEC_WAITING_FOR_SPINDLE_ORIENTED;
        return;
    }
    case EMC_TASK_PLAN_PAUSE_TYPE: plan_pause(); return;
    case EMC_TASK_PLAN_OPTIONAL_STOP_TYPE:
        if (optional_stop_) plan_pause();
        return;
    case EMC_TASK_PLAN_END_TYPE: return;
    case EMC_OPERATOR_ERROR_TYPE: case EMC_OPERATOR_TEXT_TYPE: case EMC_OPERATOR_DISPLAY_TYPE:
        operator_message(m.type, reinterpret_cast<const EMC_OPERATOR_DISPLAY &>(m).display);
        return;
    case EMC_SYSTEM_CMD_TYPE: start_system_cmd(emc_msg_as<EMC_SYSTEM_CMD>(&m)->string); return;
    default:
        issue_motion(m);
        // count the move until motion's next status does: the queue-room precondition must not
        // let one cycle push more moves than the planner can take (motion holds them in the ring,
        // which then fills while the planner waits, e.g. under feed hold)
        if (precondition_of(m.type) == EMC_TASK_EXEC_WAITING_FOR_MOTION_QUEUE) mst_.queue_depth++;
        return;
    }
}

void Task::start_input_wait(const EMC_AUX_INPUT_WAIT &w)
{
    wait_input_digital_ = w.input_type == EMC_AUX_INPUT_DIGITAL;
    wait_input_type_ = w.wait_type;
    st_.task.input_timeout = 0;
    wait_input_fresh_ = true;
    wait_input_heartbeat_ = mst_.heartbeat;
    exec_state_ = EMC_TASK_EXEC_WAITING_FOR_IO;
    if (w.wait_type == EMC_AUX_WAIT_IMMEDIATE || w.index < 0 || w.index >= EMCMOT_MAX_DIO) return;
    wait_input_index_ = w.index;
    wait_input_start_ = mst_.synch_di[w.index];
    wait_input_deadline_ = now_ + w.timeout;
}

// M100-M199: run the user's program (sh -c "path P Q") and wait for it.
void Task::start_system_cmd(const char *command)
{
    pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", command, (char *)nullptr);
        _exit(127);
    }
    if (pid < 0) {
        operator_error(std::string("can't run ") + command);
        return;
    }
    system_pid_ = pid;
    exec_state_ = EMC_TASK_EXEC_WAITING_FOR_SYSTEM_CMD;
}

// Issue list items while their preconditions hold (paused: only what a STEP allows).
void Task::execute_cycle()
{
    if (exec_state_ != EMC_TASK_EXEC_DONE) {
        if (!exec_waiting_done()) return;
        exec_state_ = EMC_TASK_EXEC_DONE;
        st_.task.delayLeft = 0;
    }
    for (int n = 0; n < ITEMS_PER_CYCLE; n++) {
        if (interp_state_ == EMC_TASK_INTERP_PAUSED) break;
        if (!has_pending_) {
            if (list_.empty()) break;
            pending_ = list_.pop();
            has_pending_ = true;
        }
        if (!precondition_met(*pending_.msg())) {
            exec_state_ = precondition_of(pending_.msg()->type);
            break;
        }
        has_pending_ = false;
        issue(pending_);
        if (exec_state_ != EMC_TASK_EXEC_DONE) break;
    }
}
