// task_state.cc: machine state (E-stop, on/off), modes and aborts (nml.md sec. 4).
#include "task.hh"

// Reported state: io E-stop -> ESTOP; motion not enabled -> ESTOP_RESET; else ON (OFF is never reported).
int Task::task_state() const
{
    if (st_.io.aux.estop) return EMC_TASK_STATE_ESTOP;
    return machine_on_ ? EMC_TASK_STATE_ON : EMC_TASK_STATE_ESTOP_RESET;
}

// Reported mode: FREE/TELEOP -> MANUAL; COORD -> the last requested of MDI/AUTO.
int Task::task_mode() const
{
    return traj_mode_ == EMC_TRAJ_MODE_COORD && requested_mode_ != EMC_TASK_MODE_MANUAL
               ? requested_mode_ : EMC_TASK_MODE_MANUAL;
}

// Forget the program/MDI in progress (no motion commands): list, queue, interpreter IDLE.
void Task::reset_plan()
{
    list_.clear();
    has_pending_ = false;
    mdi_queue_.clear();
    mdi_active_ = false;
    mdi_text_.clear();
    wait_synch_ = false;
    skipping_ = false;
    if (interp_state_ != EMC_TASK_INTERP_IDLE && file_open_) {
        interp_->close();
        file_open_ = false;
    }
    interp_state_ = EMC_TASK_INTERP_IDLE;
    exec_state_ = EMC_TASK_EXEC_DONE;
    task_paused_ = false;
    stepping_ = false;
    read_line_ = 0;
    st_.task.motionLine = 0;
    if (system_pid_ > 0) kill(system_pid_, SIGTERM);
    wait_input_index_ = -1;
    canon_->flush();
    list_.clear();
}

// EMC_TASK_ABORT and everything that stops a program: motion, spindles, io, the plan.
void Task::task_abort()
{
    state_tag_t tag = mst_.exec_tag;
    bool restore = interp_state_ != EMC_TASK_INTERP_IDLE || mdi_active_;
    MotionCommands cmds;
    xl_.motion_abort(cmds);
    xl_.motion_abort(cmds);
    xl_.spindles_off(cmds);
    send(cmds);
    io_.abort();
    reset_plan();
    if (restore) restore_tag(tag);
    run_abort_command();
    interp_synch();
}

void Task::set_state(int state)
{
    MotionCommands cmds;
    switch (state) {
    case EMC_TASK_STATE_ESTOP:
        xl_.motion_abort(cmds);
        xl_.spindles_off(cmds);
        cmds.push_back(MotionTranslator::make(EMCMOT_DISABLE));
        send_unhome_volatile(cmds);
        send(cmds);
        io_.estop_on();
        io_.coolant(false, false);
        io_.coolant(true, false);
        machine_on_ = false;
        reset_plan();
        interp_synch();
        break;
    case EMC_TASK_STATE_ESTOP_RESET:
        xl_.motion_abort(cmds);
        xl_.spindles_off(cmds);
        send(cmds);
        io_.estop_reset();
        io_.coolant(false, false);
        reset_plan();
        interp_synch();
        break;
    case EMC_TASK_STATE_ON:
        if (st_.io.aux.estop) break;
        send(MotionTranslator::make(EMCMOT_ENABLE));
        if (traj_mode_ != EMC_TRAJ_MODE_FREE) set_traj_mode(traj_mode_);
        io_.coolant(false, false);
        machine_on_ = true;
        break;
    case EMC_TASK_STATE_OFF:
        xl_.motion_abort(cmds);
        xl_.spindles_off(cmds);
        cmds.push_back(MotionTranslator::make(EMCMOT_DISABLE));
        send_unhome_volatile(cmds);
        send(cmds);
        io_.abort();
        io_.coolant(false, false);
        machine_on_ = false;
        reset_plan();
        interp_synch();
        break;
    default:
        break;
    }
}

// UNHOME -2 right after DISABLE; when motion is still enabled it is sent once motion reports
// itself disabled (motion refuses to unhome an enabled coordinated machine).
void Task::send_unhome_volatile(MotionCommands &cmds)
{
    if (mst_.enabled) {
        unhome_pending_ = true;
        return;
    }
    emcmot_command_t c = MotionTranslator::make(EMCMOT_JOINT_UNHOME);
    c.joint = EMCMOT_JOINT_VOLATILE;
    cmds.push_back(c);
}

// Motion mode command, remembered so the reported mode follows at once.
void Task::set_traj_mode(int mode)
{
    traj_mode_ = mode;
    send(MotionTranslator::make(mode == EMC_TRAJ_MODE_COORD ? EMCMOT_COORD
                                : mode == EMC_TRAJ_MODE_TELEOP ? EMCMOT_TELEOP : EMCMOT_FREE));
}

void Task::set_mode(int mode)
{
    if (jogging()) return;
    int current = task_mode();
    if (current == EMC_TASK_MODE_AUTO && interp_state_ != EMC_TASK_INTERP_IDLE && mode != EMC_TASK_MODE_AUTO) {
        operator_error("Can't switch mode while mode is AUTO and interpreter is not IDLE");
        return;
    }
    if (mode == EMC_TASK_MODE_MANUAL) {
        if (current != EMC_TASK_MODE_MANUAL) {
            MotionCommands cmds;
            xl_.motion_abort(cmds);
            send(cmds);
            reset_plan();
        }
        requested_mode_ = mode;
        set_traj_mode(all_homed() ? EMC_TRAJ_MODE_TELEOP : EMC_TRAJ_MODE_FREE);
        return;
    }
    if (mode != EMC_TASK_MODE_MDI && mode != EMC_TASK_MODE_AUTO) return;
    if (current == mode && traj_mode_ == EMC_TRAJ_MODE_COORD) return;
    requested_mode_ = mode;
    set_traj_mode(EMC_TRAJ_MODE_COORD);
    MotionCommands cmds;
    xl_.motion_abort(cmds);
    send(cmds);
    reset_plan();
    interp_synch();
}

// E-stop and motion faults: leaving ON aborts everything (nml.md sec. 4).
void Task::estop_sync()
{
    bool estop = st_.io.aux.estop;
    if (estop && !estop_seen_ && machine_on_) {
        MotionCommands cmds;
        xl_.motion_abort(cmds);
        xl_.spindles_off(cmds);
        cmds.push_back(MotionTranslator::make(EMCMOT_DISABLE));
        send_unhome_volatile(cmds);
        send(cmds);
        io_.coolant(false, false);
        io_.coolant(true, false);
        machine_on_ = false;
        reset_plan();
        interp_synch();
    }
    estop_seen_ = estop;
    bool echoed = (int32_t)(mst_.echo.serial - last_serial_) >= 0;
    if (machine_on_ && echoed && !mst_.enabled) {
        machine_on_ = false;
        MotionCommands cmds;
        xl_.spindles_off(cmds);
        send(cmds);
        io_.abort();
        reset_plan();
        interp_synch();
    }
    if (echoed && unhome_pending_ && !mst_.enabled) {
        unhome_pending_ = false;
        MotionCommands cmds;
        send_unhome_volatile(cmds);
        send(cmds);
    }
    // a disabled machine keeps its mode (E-stop in AUTO stays AUTO)
    if (echoed && mst_.enabled)
        traj_mode_ = mst_.coord ? EMC_TRAJ_MODE_COORD : mst_.teleop ? EMC_TRAJ_MODE_TELEOP : EMC_TRAJ_MODE_FREE;
}
