// responder.hh: nml_responder, a small stand-in for task that the Python module tests talk to.
#ifndef RESPONDER_HH
#define RESPONDER_HH

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "emc_nml.hh"

// Configuration read from the INI file.
struct ResponderConfig {
    std::string ini_path;
    std::string nml_file;
    std::string tool_table;
    int joints = 3;
    int spindles = 1;
    int axis_mask = 7;
    int num_dio = 4;
    int num_aio = 4;
    double linear_units = 1.0;  // machine units per mm
    double angular_units = 1.0;
    double cycle_s = 0.001;
    double servo_s = 0.001;
    double max_velocity = 1.0;
    double max_acceleration = 1.0;
    double default_velocity = 1.0;
    double default_acceleration = 1.0;
    bool no_force_homing = false;
};

// A running MDI or program step: what the interpreter does until `until`.
struct Activity {
    std::string text;
    double until = 0;      // monotonic time when it completes
    int exec_state = EMC_TASK_EXEC_DONE;
    bool has_target = false;
    double target[9] = {};
};

// Everything the responder simulates.
struct Machine {
    ResponderConfig cfg;
    std::unique_ptr<EmcChannel> cmd, stat, err;
    tooldata_t *tools = nullptr;
    std::vector<tooldata_entry_t> tool_table;
    double now = 0;          // monotonic seconds of this cycle
    // task
    bool estop = true, enabled = false;
    int requested_mode = EMC_TASK_MODE_MANUAL;
    int traj_mode = EMC_TRAJ_MODE_FREE;
    int interp = EMC_TASK_INTERP_IDLE;
    bool rejected = false;    // last command rejected: RCS_ERROR until the next one
    int32_t echo_serial = 0;
    NMLTYPE command_type = 0;
    std::deque<std::string> mdi_queue;
    Activity activity;        // current MDI (interp READING)
    bool paused = false;
    std::string program;
    int program_lines = 0, program_line = 0;
    double next_line_at = 0;
    // motion
    double pos[9] = {};
    double jog_vel[9] = {};
    double jog_target[9] = {};
    bool jog_to_target[9] = {};
    double joint_jog_vel[EMCMOT_MAX_JOINTS] = {};
    double home_done_at[EMCMOT_MAX_JOINTS] = {};
    bool homed[EMCMOT_MAX_JOINTS] = {};
    // everything else lives directly in the status we publish
    EMC_STAT status;
};

// Read the INI file; false with a message on stderr.
bool responder_load_config(const std::string &ini, ResponderConfig &cfg);
// Load the tool table file into m.tool_table (LinuxCNC format) and publish it.
bool responder_load_tools(Machine &m, const std::string &path);
void responder_publish_tools(Machine &m);
// Handle one command read from emcCommand.
void responder_handle(Machine &m, const NMLmsg &msg);
// Advance simulated time by one cycle (homing, jogs, MDI, programs).
void responder_advance(Machine &m, double dt);
// Fill m.status from the simulation and write it to emcStatus.
void responder_publish_status(Machine &m);
// Queue an operator error on emcError.
void responder_error(Machine &m, const std::string &text);
// True when every configured joint is homed.
bool responder_all_homed(const Machine &m);
// Reported task state / mode (derived as nml.md sec. 4 describes).
int responder_task_state(const Machine &m);
int responder_task_mode(const Machine &m);
// Stop everything running (abort): MDI queue, program, jogs.
void responder_abort(Machine &m);

#endif
