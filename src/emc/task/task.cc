// task.cc: milltask's life cycle: set-up, the cycle in LinuxCNC's order, shut-down, operator messages.
#include "task.hh"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <ctime>
#include <unistd.h>

double task_now()
{
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

Task::Task(const MachineConfig &cfg)
    : cfg_(cfg), xl_(cfg), io_(cfg.tool_table, cfg.random_toolchanger), inihal_(cfg)
{
    canon_ = std::make_unique<TaskCanon>(machine_canon_config(cfg), *this, list_);
    emc_set_text(st_.task.ini_filename, cfg.ini_path.c_str());
}

Task::~Task() = default;

bool Task::init(std::string *error)
{
    std::string nml = emc_nml_file_for_ini(cfg_.ini_path, error);
    if (nml.empty()) return false;
    cmd_ch_ = EmcChannel::open(nml, "emcCommand", "emc", error);
    if (cmd_ch_) stat_ch_ = EmcChannel::open(nml, "emcStatus", "emc", error);
    if (stat_ch_) err_ch_ = EmcChannel::open(nml, "emcError", "emc", error);
    if (!err_ch_) return false;
    char why[256];
    tooldata_ = tooldata_open(0, why, sizeof why);
    if (!tooldata_) tooldata_ = tooldata_open(1, why, sizeof why);
    std::vector<std::string> errors;
    if (!cfg_.tool_table.empty()) io_.load_tools(cfg_.tool_table, &errors);
    for (const std::string &e : errors) fprintf(stderr, "milltask: %s\n", e.c_str());
    publish_tools();
    if (!io_.create_hal(error)) return false;
    if (!init_interp(error)) return false;
    run_startup_code();
    now_ = next_cycle_ = task_now();
    update_status();
    return inihal_.create(error);
}

void Task::reject(const std::string &text)
{
    if (!text.empty()) operator_error(text);
    command_failed_ = true;
}

void Task::operator_error(const std::string &text)
{
    operator_message(EMC_OPERATOR_ERROR_TYPE, text);
}

void Task::operator_message(NMLTYPE kind, const std::string &text)
{
    if (err_ch_) emc_send_operator_message(*err_ch_, kind, text.c_str());
}

// One cycle: command, plan, execute, motion/io status, E-stop, status.
bool Task::cycle()
{
    now_ = task_now();
    if (!attach_motion()) return false;
    if (motion_ready_ && !emcmot_owner_alive(mot_)) {
        fprintf(stderr, "milltask: motion went away\n");
        return false;
    }
    read_motion();
    forward_motion_errors();
    io_.update(st_.io);
    estop_sync();
    if (motion_ready_) {
        // like LinuxCNC, a command is read only once motion has handled the previous one's
        const NMLmsg *msg = command_ready() ? cmd_ch_->read() : nullptr;
        if (msg) {
            echo_serial_ = msg->serial_number;
            echo_type_ = (int)msg->type;
            echo_pending_ = true;
            handle_command(*msg);
        } else if (!cmd_ch_->error().empty()) {
            fprintf(stderr, "milltask: %s\n", cmd_ch_->error().c_str());
        }
        plan_cycle();
        execute_cycle();
        MotionCommands ini_cmds;
        inihal_.check(ini_cmds);
        send(ini_cmds);
        forward_motion_errors();
        check_rejections();
    }
    if (io_.table().random() && io_.take_table_changed()) {
        std::string err = io_.save();
        if (!err.empty()) operator_error(err);
        const auto &rows = io_.table().rows();
        if (tooldata_) tooldata_publish(tooldata_, rows.data(), (int)rows.size());
        if (interp_) interp_->set_tools(io_.table().canon_tools());
    }
    publish_tools();
    io_.update(st_.io);
    update_status();
    if (exec_error_ && !command_failed_) exec_error_ = false;
    return true;
}

// A command is read once motion handled the previous one's; a joint home request also waits
// for a homing in progress to end (homemod runs one homing at a time, so back-to-back
// home(0), home(1), home(2) would otherwise be refused).
bool Task::command_ready()
{
    if (!motion_echoed()) return false;
    if (!mst_.homing_active) return true;
    const NMLmsg *next = cmd_ch_->peek();
    return !next || next->type != EMC_JOINT_HOME_TYPE;
}

// Sleep until the next period; a new command wakes task early.
void Task::wait_next_cycle()
{
    double period = cfg_.cycle_time > 0 ? cfg_.cycle_time : 0;
    next_cycle_ += period;
    double now = task_now();
    if (next_cycle_ < now - period) next_cycle_ = now;
    double left = next_cycle_ - now;
    if (left <= 0) return;
    if (cmd_ch_) cmd_ch_->wait_change(cmd_ch_->change_count(), left);
}

void Task::shutdown()
{
    if (motion_ready_ && emcmot_owner_alive(mot_)) send(MotionTranslator::make(EMCMOT_DISABLE));
    if (interp_) interp_->exit();
    if (!remote_path_.empty()) unlink(remote_path_.c_str());
    std::string err = io_.save();
    if (!err.empty()) fprintf(stderr, "milltask: %s\n", err.c_str());
    inihal_.destroy();
    io_.destroy_hal();
    if (mot_) emcmot_detach(mot_);
    mot_ = nullptr;
    if (tooldata_) tooldata_close(tooldata_);
    tooldata_ = nullptr;
}
