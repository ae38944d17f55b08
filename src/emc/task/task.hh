// task.hh: milltask, the task controller: state machine, interpreter, interp list, status, io control (nml.md sec. 4-5).
#ifndef TASK_HH
#define TASK_HH

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "emc_nml.hh"
#include "inihal.hh"
#include "interp.hh"
#include "io_control.hh"
#include "machine_config.hh"
#include "motion_client.h"
#include "motion_translate.hh"
#include "task_canon.hh"

class Task : public CanonMachine {
public:
    explicit Task(const MachineConfig &cfg);
    ~Task() override;
    // NML channels, tool table, interpreter, HAL components (inihal last). false with *error.
    bool init(std::string *error);
    // One task cycle (nml.md sec. 2 loop order). false once task cannot go on.
    bool cycle();
    // Machine off, interpreter exit (parameter file), HAL components and channels released.
    void shutdown();
    // Sleep until the next cycle is due (or a command arrives).
    void wait_next_cycle();

    // ---- CanonMachine (status-based answers for the interpreter's queries) ----
    EmcPose position() override { return mst_.carte_pos_cmd; }
    EmcPose probed_position() override { return mst_.probed_pos; }
    double probe_tripped_value() override { return mst_.probe_val; }
    int digital_input(int index) override { return mst_.synch_di[index]; }
    double analog_input(int index) override { return mst_.analog_input[index]; }
    int tool_slot() override { return 0; }
    int selected_tool_slot() override { return io_.prepped_index(); }
    int tool_index(int toolno) override;
    bool queue_empty() override { return mst_.queue_depth == 0; }
    int toolchanger_fault() override { return 0; }
    int toolchanger_reason() override { return 0; }

    // ---- used by the command handlers (task_command.cc) ----
    int task_mode() const;
    int task_state() const;
    void reject(const std::string &text);         // error message + RCS_ERROR until the next command
    void operator_error(const std::string &text);
    void operator_message(NMLTYPE kind, const std::string &text);
    void set_state(int state);
    void set_mode(int mode);
    void task_abort();
    void issue_motion(const NMLmsg &msg);
    void plan_open(const std::string &file);
    void plan_open_msg(const EMC_TASK_PLAN_OPEN &m);
    void plan_close();
    void plan_run(int line);
    void plan_pause();
    void plan_resume();
    void plan_step();
    void plan_execute(const std::string &text);
    void plan_init();
    void plan_synch();
    void tool_load_table(const std::string &file);
    void tool_set_offset(const EMC_TOOL_SET_OFFSET &m);
    void tool_set_number(int index);
    void coolant(bool mist, bool on);
    void spindle_speed(const EMC_SPINDLE_SPEED &m);
    void set_optional_stop(bool on);
    void set_block_delete(bool on);
    void set_debug(int debug) { st_.debug = debug; }
    bool all_homed() const;
    bool check_io_index(const NMLmsg &msg);
    bool jogging() const { return mst_.jogging_active != 0; }
    const MachineConfig &config() const { return cfg_; }
    EMC_STAT &stat() { return st_; }

private:
    // motion link (task_motion.cc)
    bool attach_motion();
    void send(MotionCommands &cmds);
    void send(emcmot_command_t c);
    void read_motion();
    void forward_motion_errors();
    void check_rejections();
    bool motion_done() const;
    bool motion_queue_room() const;
    bool motion_echoed() const;
    bool command_ready();
    // plan (task_plan.cc)
    void plan_cycle();
    void read_ahead();
    bool execute_line_result(InterpStatus st, bool mdi);
    void start_mdi(const std::string &text);
    void mdi_cycle();
    void mdi_call_lines();
    void program_cycle();
    void interp_error(bool mdi);
    void finish_synch();
    void interp_synch();
    void run_abort_command();
    void run_startup_code();
    void restore_tag(const state_tag_t &t);
    void restore_origin(int code);
    void drop_output_since(size_t keep);
    // execute (task_execute.cc)
    void execute_cycle();
    bool precondition_met(const NMLmsg &msg);
    void issue(const QueuedMsg &q);
    bool exec_waiting_done();
    bool input_wait_done();
    void start_input_wait(const EMC_AUX_INPUT_WAIT &w);
    void start_system_cmd(const char *command);
    // status (task_status.cc)
    void update_status();
    void update_echo();
    void fill_motion_status();
    void fill_task_status();
    int rcs_status() const;
    // interpreter (task_interp.cc)
    bool init_interp(std::string *error);
    void interp_tag(state_tag_t &tag) const;
    void interp_codes(int32_t *g, int32_t *m, double *s) const;
    bool user_m(int m, double p, double q);
    // commands (task_command.cc)
    void handle_command(const NMLmsg &msg);
    void estop_sync();
    void reset_plan();
    void set_traj_mode(int mode);
    void send_unhome_volatile(MotionCommands &cmds);
    void publish_tools();

    MachineConfig cfg_;
    std::unique_ptr<EmcChannel> cmd_ch_, stat_ch_, err_ch_;
    emcmot_client_t *mot_ = nullptr;
    bool motion_ready_ = false;
    double attach_deadline_ = 0;
    emcmot_status_t mst_ = {};
    uint32_t last_serial_ = 0;
    // the command read last: its serial is echoed once motion took what it issued
    int echo_serial_ = 0, echo_type_ = 0;
    bool echo_pending_ = false;
    uint32_t seen_rejected_ = 0;
    MotionTranslator xl_;
    InterpList list_;
    IoControl io_;
    IniHal inihal_;
    std::unique_ptr<TaskCanon> canon_;
    std::unique_ptr<Interp> interp_;
    tooldata_t *tooldata_ = nullptr;
    EMC_STAT st_;
    double now_ = 0, next_cycle_ = 0;

    // task state
    int requested_mode_ = EMC_TASK_MODE_MANUAL;
    int interp_state_ = EMC_TASK_INTERP_IDLE;
    int exec_state_ = EMC_TASK_EXEC_DONE;
    bool command_failed_ = false;     // RCS_ERROR until the next command is read
    bool exec_error_ = false;         // exec ERROR shown for one cycle
    bool machine_on_ = false;         // motion enabled by us (leaving ON aborts)
    bool task_paused_ = false;
    bool stepping_ = false;
    int step_budget_ = 0;             // list items a STEP may still issue while paused
    int paused_from_ = EMC_TASK_INTERP_IDLE;
    bool optional_stop_ = true, block_delete_ = true;
    // program / MDI
    std::string file_;
    std::string remote_name_, remote_path_;   // a program arriving in PLAN_OPEN chunks
    long remote_size_ = 0, remote_received_ = 0;
    bool file_open_ = false;
    int start_line_ = 0;              // run from line: output of earlier main-program lines dropped
    bool skipping_ = false;
    bool verify_only_ = false;
    bool wait_synch_ = false;         // an execute-finish block: stop reading until the list drains
    CanonBlockNeeds synch_needs_;
    std::deque<std::string> mdi_queue_;
    bool mdi_active_ = false;
    std::string mdi_text_;
    int read_line_ = 0, current_line_ = 0;
    int errcode_ = 0;
    // execution
    bool has_pending_ = false;
    QueuedMsg pending_;
    double delay_until_ = 0;
    int wait_input_index_ = -1;
    bool wait_input_digital_ = true;
    int wait_input_type_ = 0;
    double wait_input_deadline_ = 0;
    int wait_input_start_ = 0;
    bool wait_input_fresh_ = false;   // M66: inputs not yet sampled by motion since it was issued
    uint32_t wait_input_heartbeat_ = 0;
    double orient_deadline_ = 0;
    int orient_spindle_ = 0;
    pid_t system_pid_ = -1;
    bool estop_seen_ = true;
    bool unhome_pending_ = false;     // UNHOME -2 waits for motion to report itself disabled
    int traj_mode_ = EMC_TRAJ_MODE_FREE;   // motion mode commanded (or reported once echoed)
};

double task_now();

#endif
