// task_plan.cc: programs (open, run from line, readahead, pause/resume/step) and the MDI queue (nml.md sec. 4).
#include "task.hh"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace {
const int INTERP_ERRCODE = 5;        // LinuxCNC's INTERP_ERROR as reported in interpreter_errcode
const int LINES_PER_CYCLE = 200;     // readahead burst bound
}

// Messages kept from lines skipped by "run from line": settings, not actions.
static bool kept_when_skipping(NMLTYPE t)
{
    return t == EMC_TRAJ_SET_G5X_TYPE || t == EMC_TRAJ_SET_G92_TYPE || t == EMC_TRAJ_SET_ROTATION_TYPE ||
           t == EMC_TRAJ_SET_OFFSET_TYPE || t == EMC_TRAJ_SET_TERM_COND_TYPE ||
           t == EMC_TRAJ_SET_SPINDLESYNC_TYPE || t == EMC_TRAJ_SET_FO_ENABLE_TYPE ||
           t == EMC_TRAJ_SET_SO_ENABLE_TYPE || t == EMC_TRAJ_SET_FH_ENABLE_TYPE;
}

// Drop what the interpreter produced since the list held `keep` items (except settings).
void Task::drop_output_since(size_t keep)
{
    canon_->flush();
    size_t n = list_.size();
    std::vector<QueuedMsg> all;
    for (size_t i = 0; i < n; i++) all.push_back(list_.pop());
    for (size_t i = 0; i < n; i++)
        if (i < keep || kept_when_skipping(all[i].msg()->type)) list_.append_copy(all[i]);
}

void Task::plan_open(const std::string &file)
{
    if (file_open_) interp_->close();
    file_open_ = false;
    try {
        interp_->open(file);
    } catch (const std::exception &e) {
        operator_error(e.what());
        reject("can't open " + file);
        return;
    }
    file_ = file;
    file_open_ = true;
    emc_set_text(st_.task.file, file.c_str());
}

// PLAN_OPEN with remote_buffersize > 0: a remote client sends the file in chunks; task keeps
// them in a temporary copy and opens it once remote_filesize bytes arrived (task.file = the name sent).
void Task::plan_open_msg(const EMC_TASK_PLAN_OPEN &m)
{
    if (m.remote_buffersize <= 0) {
        plan_open(m.file);
        return;
    }
    if (m.remote_buffersize > EMC_TASK_PLAN_OPEN_REMOTE_BUFFER || m.remote_filesize < 0) {
        reject(std::string("can't open ") + m.file + ": bad remote chunk");
        return;
    }
    if (remote_name_ != m.file || remote_received_ >= remote_size_) {
        const char *tmp = getenv("TMPDIR");
        std::string base = m.file;
        size_t slash = base.rfind('/');
        if (slash != std::string::npos) base = base.substr(slash + 1);
        remote_path_ = std::string(tmp && *tmp ? tmp : "/tmp") + "/openemc-remote-" + std::to_string(getpid()) + "-" + base;
        remote_name_ = m.file;
        remote_size_ = m.remote_filesize;
        remote_received_ = 0;
        unlink(remote_path_.c_str());
    }
    FILE *f = fopen(remote_path_.c_str(), "ab");
    if (!f || fwrite(m.remote_buffer, 1, (size_t)m.remote_buffersize, f) != (size_t)m.remote_buffersize) {
        if (f) fclose(f);
        reject("can't open " + remote_path_ + ": " + strerror(errno));
        return;
    }
    fclose(f);
    remote_received_ += m.remote_buffersize;
    if (remote_received_ < remote_size_) return;
    plan_open(remote_path_);
    if (file_open_) emc_set_text(st_.task.file, m.file);
}

void Task::plan_close()
{
    if (file_open_) interp_->close();
    file_open_ = false;
}

// PLAN_INIT: interpreter back to its start-up state (and the start-up code).
void Task::plan_init()
{
    reset_plan();
    try {
        interp_->init();
    } catch (const std::exception &e) {
        operator_error(e.what());
    }
    list_.clear();
    interp_synch();
}

void Task::plan_synch()
{
    interp_synch();
}

// PLAN_RUN: line 0 from the start; n > 0 read lines < n without executing them; n < 0 verify.
void Task::plan_run(int line)
{
    if (task_mode() != EMC_TASK_MODE_AUTO) return;
    if (!all_homed() && !cfg_.no_force_homing) {
        reject("Can't run a program when not homed");
        return;
    }
    if (!file_open_) {
        if (file_.empty()) return;
        plan_open(file_);
        if (!file_open_) return;
    }
    interp_synch();
    start_line_ = line;
    verify_only_ = line < 0;
    skipping_ = line != 0;
    task_paused_ = false;
    interp_state_ = EMC_TASK_INTERP_READING;
    exec_state_ = EMC_TASK_EXEC_DONE;
}

// One interpreter line's output and result while running a program.
void Task::read_ahead()
{
    size_t max = (size_t)cfg_.interp_max_len;
    for (int n = 0; n < LINES_PER_CYCLE && interp_state_ == EMC_TASK_INTERP_READING && !wait_synch_; n++) {
        if (list_.size() > max * 2 / 3 && !skipping_) break;
        int level = interp_->state().call_level;
        size_t keep = list_.size();
        InterpStatus st = interp_->execute_next();
        int seq = interp_->state().sequence_number;
        if (skipping_) {
            if (level == 0 && !verify_only_ && seq >= start_line_) skipping_ = false;
            else {
                drop_output_since(keep);
                canon_->set_position(mst_.carte_pos_cmd);
            }
        }
        if (level == 0) read_line_ = seq;
        if (!execute_line_result(st, false)) break;
    }
}

// React to one interpreter result; false when reading must stop for now.
bool Task::execute_line_result(InterpStatus st, bool mdi)
{
    CanonBlockNeeds needs = canon_->take_needs();
    if (st == INTERP_ERROR) {
        if (!mdi && interp_->at_end_of_file() && skipping_) {
            canon_->flush();
            skipping_ = false;
            interp_state_ = EMC_TASK_INTERP_WAITING;
            return false;
        }
        interp_error(mdi);
        return false;
    }
    if (st == INTERP_EXIT) {
        canon_->flush();
        if (mdi) {
            command_failed_ = true;
            mdi_queue_.clear();
        }
        if (!mdi) interp_state_ = EMC_TASK_INTERP_WAITING;
        return false;
    }
    if (st == INTERP_EXECUTE_FINISH || needs.probe || needs.wait_input || needs.tool_data) {
        canon_->flush();
        if (skipping_) return true;
        wait_synch_ = true;
        synch_needs_ = needs;
        return false;
    }
    return true;
}

// The interpreter's message is the only error; output not yet issued is dropped.
void Task::interp_error(bool mdi)
{
    operator_error(interp_->error_text());
    errcode_ = INTERP_ERRCODE;
    canon_->take_needs();
    list_.clear();
    has_pending_ = false;
    wait_synch_ = false;
    skipping_ = false;
    if (mdi) {
        exec_error_ = true;
        command_failed_ = true;
        mdi_queue_.clear();
        mdi_active_ = false;
        mdi_text_.clear();
        interp_state_ = EMC_TASK_INTERP_IDLE;
        interp_synch();
        return;
    }
    if (file_open_) interp_->close();
    file_open_ = false;
    interp_state_ = EMC_TASK_INTERP_WAITING;
}

// AUTO: read ahead; at the end wait for motion, then close the program.
void Task::program_cycle()
{
    if (wait_synch_ && list_.empty() && !has_pending_ && exec_state_ == EMC_TASK_EXEC_DONE &&
        motion_done() && io_.done())
        finish_synch();
    if (interp_state_ == EMC_TASK_INTERP_READING) read_ahead();
    if (interp_state_ == EMC_TASK_INTERP_WAITING && list_.empty() && !has_pending_ && !wait_synch_ &&
        exec_state_ == EMC_TASK_EXEC_DONE && motion_done() && io_.done()) {
        if (file_open_) interp_->close();
        file_open_ = false;
        interp_state_ = EMC_TASK_INTERP_IDLE;
        read_line_ = 0;
        verify_only_ = false;
        interp_synch();
    }
}

void Task::finish_synch()
{
    wait_synch_ = false;
    interp_synch();
}

void Task::plan_execute(const std::string &text)
{
    if (!all_homed() && !cfg_.no_force_homing) {
        reject("Can't issue MDI command when not homed");
        return;
    }
    if (task_mode() != EMC_TASK_MODE_MDI) {
        reject("Must be in MDI mode to issue MDI command");
        return;
    }
    if (!mdi_active_ && mdi_queue_.empty() && list_.empty() && !has_pending_ && !wait_synch_) {
        start_mdi(text);
        return;
    }
    mdi_queue_.push_back(text);
}

void Task::start_mdi(const std::string &text)
{
    // at rest the interpreter starts from where the machine is (LinuxCNC synchs before MDI)
    if (motion_done() && io_.done()) interp_synch();
    mdi_active_ = true;
    mdi_text_ = text;
    interp_state_ = EMC_TASK_INTERP_READING;
    InterpStatus st = interp_->execute_line(text);
    read_line_ = interp_->state().sequence_number;
    execute_line_result(st, true);
}

// MDI: continue a multi-line call, hand over the next queued text, finish when all is done.
void Task::mdi_cycle()
{
    if (wait_synch_ && list_.empty() && !has_pending_ && exec_state_ == EMC_TASK_EXEC_DONE &&
        motion_done() && io_.done())
        finish_synch();
    for (int n = 0; mdi_active_ && !wait_synch_ && interp_->state().call_level > 0 && n < LINES_PER_CYCLE; n++) {
        InterpStatus st = interp_->execute_next();
        if (!execute_line_result(st, true)) break;
    }
    if (!mdi_active_ || wait_synch_ || interp_->state().call_level > 0) return;
    if (!list_.empty() || has_pending_) return;
    if (!mdi_queue_.empty()) {
        std::string next = mdi_queue_.front();
        mdi_queue_.pop_front();
        start_mdi(next);
        return;
    }
    if (exec_state_ == EMC_TASK_EXEC_DONE && motion_done() && io_.done()) {
        mdi_active_ = false;
        mdi_text_.clear();
        interp_state_ = EMC_TASK_INTERP_IDLE;
    }
}

// Plan phase of the cycle: programs in AUTO, the MDI queue in MDI.
void Task::plan_cycle()
{
    if (task_mode() == EMC_TASK_MODE_MDI) mdi_cycle();
    else if (task_mode() == EMC_TASK_MODE_AUTO) program_cycle();
}

// PLAN_PAUSE: hold motion; the interpreter waits in PAUSED until RESUME.
void Task::plan_pause()
{
    send(MotionTranslator::make(EMCMOT_PAUSE));
    if (interp_state_ != EMC_TASK_INTERP_PAUSED) paused_from_ = interp_state_;
    interp_state_ = EMC_TASK_INTERP_PAUSED;
    task_paused_ = true;
}

void Task::plan_resume()
{
    stepping_ = false;
    send(MotionTranslator::make(EMCMOT_RESUME));
    if (interp_state_ == EMC_TASK_INTERP_PAUSED)
        interp_state_ = paused_from_ == EMC_TASK_INTERP_IDLE && task_mode() != EMC_TASK_MODE_MANUAL
                            ? EMC_TASK_INTERP_READING : paused_from_;
    if (interp_state_ == EMC_TASK_INTERP_PAUSED) interp_state_ = EMC_TASK_INTERP_IDLE;
    task_paused_ = false;
}

// STEP: from idle, start the program paused; while paused, run one more segment.
void Task::plan_step()
{
    if (task_mode() != EMC_TASK_MODE_AUTO) return;
    stepping_ = true;
    if (interp_state_ == EMC_TASK_INTERP_IDLE) {
        plan_run(0);
        if (interp_state_ != EMC_TASK_INTERP_READING) return;
        send(MotionTranslator::make(EMCMOT_PAUSE));
        paused_from_ = EMC_TASK_INTERP_READING;
        interp_state_ = EMC_TASK_INTERP_PAUSED;
        task_paused_ = true;
        step_budget_ = 0;
        return;
    }
    if (interp_state_ == EMC_TASK_INTERP_PAUSED) {
        send(MotionTranslator::make(EMCMOT_STEP));
        step_budget_ = 1;
        return;
    }
}

void Task::set_optional_stop(bool on) { optional_stop_ = on; canon_->set_switches(block_delete_, on); }

void Task::set_block_delete(bool on)
{
    block_delete_ = on;
    interp_->set_block_delete(on);
    canon_->set_switches(on, optional_stop_);
}
