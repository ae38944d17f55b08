// task_motion.cc: task's link to motion: attach (with retries while HAL files load motmod), push, status, messages.
#include "task.hh"

#include <cerrno>
#include <cstring>
#include <unistd.h>

namespace {
const double ATTACH_TIMEOUT_S = 10.0;   // launcher: task retries while the HAL files load motmod
const double RING_RETRY_S = 0.0002;
// Queued moves wait in the interp list while the command ring holds this many commands (a
// quarter of it: the rest stays free for immediate commands such as pause, abort, overrides).
const unsigned MOTION_RING_QUEUE_LIMIT = EMCMOT_RING_CAPACITY / 4;
}

// Attach once motion exists; then configure it and start in E-stop, MANUAL.
bool Task::attach_motion()
{
    if (motion_ready_) return true;
    if (attach_deadline_ == 0) attach_deadline_ = now_ + ATTACH_TIMEOUT_S;
    char why[256] = "";
    int rc = emcmot_attach(cfg_.shmem_key, EMCMOT_ATTACH_PRODUCER, &mot_, why, sizeof why);
    if (rc < 0) {
        mot_ = nullptr;
        if (now_ < attach_deadline_ && (rc == -ENOENT || rc == -EPROTO)) return true;
        fprintf(stderr, "milltask: can't attach to motion: %s\n", why);
        return false;
    }
    MotionCommands cmds;
    xl_.startup(cmds);
    for (int j = 0; j < cfg_.joints; j++) {
        if (cfg_.joint[j].comp_file.empty()) continue;
        EMC_JOINT_LOAD_COMP lc;
        lc.joint = j;
        lc.type = cfg_.joint[j].comp_file_type;
        emc_set_text(lc.file, cfg_.joint[j].comp_file.c_str());
        std::string err;
        xl_.translate(lc, cmds, &err);
        if (!err.empty()) {
            fprintf(stderr, "milltask: %s\nmilltask: emcMotionInit: emcJointInit(%d) failed\n", err.c_str(), j);
            return false;
        }
    }
    send(cmds);
    motion_ready_ = true;
    read_motion();
    // the interpreter is initialised again now that motion answers its queries; as in LinuxCNC
    // this rewrites the parameter file a second time (so <PARAMETER_FILE>.bak exists after start-up)
    plan_init();
    run_startup_code();
    set_state(EMC_TASK_STATE_ESTOP);
    set_mode(EMC_TASK_MODE_MANUAL);
    return true;
}

// Queue every command; a full ring is waited on (bounded by [EMCMOT]COMM_TIMEOUT).
void Task::send(MotionCommands &cmds)
{
    for (emcmot_command_t &c : cmds) send(c);
    cmds.clear();
}

void Task::send(emcmot_command_t c)
{
    if (!mot_) return;
    double deadline = task_now() + cfg_.comm_timeout;
    for (;;) {
        long serial = emcmot_push(mot_, &c);
        if (serial > 0) { last_serial_ = (uint32_t)serial; return; }
        if (serial != -EAGAIN || task_now() > deadline) {
            operator_error(std::string("motion command ") + (emcmot_command_name(c.command) ?: "?") +
                           " not queued: " + strerror((int)-serial));
            return;
        }
        usleep((useconds_t)(RING_RETRY_S * 1e6));
    }
}

// Room for another queued move: the planner has room, and the command ring is no more than a
// quarter full, so moves motion cannot take yet (planner full, feed hold) wait here, in the
// interp list, instead of filling the ring and blocking task in send().
bool Task::motion_queue_room() const
{
    if (mst_.queue_full || mst_.queue_depth >= mst_.queue_capacity - 1) return false;
    return !mot_ || emcmot_pending(mot_) < MOTION_RING_QUEUE_LIMIT;
}

// Translate an NML message for motion and queue the result.
void Task::issue_motion(const NMLmsg &msg)
{
    MotionCommands cmds;
    std::string err;
    xl_.translate(msg, cmds, &err);
    if (!err.empty()) operator_error(err);
    send(cmds);
}

void Task::read_motion()
{
    if (!mot_) return;
    emcmot_status_t s;
    if (emcmot_read_status(mot_, &s) == 0) mst_ = s;
}

// Motion's operator messages go to emcError as they are.
void Task::forward_motion_errors()
{
    if (!mot_) return;
    char buf[EMCMOT_ERROR_LEN];
    int kind;
    while (emcmot_pop_error(mot_, buf, sizeof buf, &kind) == 1) {
        NMLTYPE t = kind == EMCMOT_MSG_TEXT ? EMC_OPERATOR_TEXT_TYPE
                  : kind == EMCMOT_MSG_DISPLAY ? EMC_OPERATOR_DISPLAY_TYPE : EMC_OPERATOR_ERROR_TYPE;
        operator_message(t, buf);
    }
}

// A move motion refused stops the program (the machine stays on); motion already said why.
void Task::check_rejections()
{
    const emcmot_echo_t &e = mst_.echo;
    if (e.rejected == seen_rejected_) return;
    uint32_t fresh = e.rejected - seen_rejected_;
    seen_rejected_ = e.rejected;
    bool move = false;
    for (uint32_t i = 0; i < fresh && i < EMCMOT_REJECT_HISTORY; i++) {
        const emcmot_reject_t &r = e.reject[(e.reject_next + EMCMOT_REJECT_HISTORY - 1 - i) % EMCMOT_REJECT_HISTORY];
        if (!r.reported && r.reason[0]) operator_error(r.reason);
        if (r.command == EMCMOT_SET_LINE || r.command == EMCMOT_SET_CIRCLE || r.command == EMCMOT_PROBE ||
            r.command == EMCMOT_RIGID_TAP)
            move = true;
    }
    if (move && (interp_state_ != EMC_TASK_INTERP_IDLE || !list_.empty())) {
        task_abort();
        command_failed_ = true;
    }
}

// Motion has handled every command task queued.
bool Task::motion_echoed() const
{
    return !mot_ || (int32_t)(mst_.echo.serial - last_serial_) >= 0;
}

// Everything queued was handled and the planner is empty and in position.
bool Task::motion_done() const
{
    if (!mot_) return true;
    if ((int32_t)(mst_.echo.serial - last_serial_) < 0) return false;
    return mst_.queue_depth == 0 && mst_.inpos;
}

bool Task::all_homed() const
{
    for (int j = 0; j < cfg_.joints; j++)
        if (!mst_.joint[j].homed) return false;
    return true;
}
