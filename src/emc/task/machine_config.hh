// machine_config.hh: the INI values task needs ([TRAJ], [KINS], [JOINT_n], [AXIS_L], [SPINDLE_n], [TASK], [EMCIO], [DISPLAY]).
#ifndef MACHINE_CONFIG_HH
#define MACHINE_CONFIG_HH

#include <string>
#include <vector>

#include "canon_limits.h"
#include "motion_cmd.h"

// One [JOINT_n] section (machine units).
struct JointConfig {
    int type = 1;                   // 1 linear, 2 angular
    double units = 1.0;             // machine units per mm or per degree
    double min_limit = -1e99, max_limit = 1e99;
    double max_velocity = 1.0, max_acceleration = 1.0, max_jerk = 0;
    double backlash = 0;
    double ferror = 1.0, min_ferror = 1.0;
    double home = 0, home_offset = 0;
    double home_search_vel = 0, home_latch_vel = 0, home_final_vel = -1;
    bool home_use_index = false, home_ignore_limits = false, home_is_shared = false;
    bool home_index_no_encoder_reset = false, volatile_home = false, locking_indexer = false;
    int home_absolute_encoder = 0;
    int home_sequence = 999;
    std::string comp_file;
    int comp_file_type = 0;
};

// One [AXIS_L] section.
struct AxisConfig {
    double min_limit = -1e99, max_limit = 1e99;
    double max_velocity = 1.0, max_acceleration = 1.0, max_jerk = 0;
    double offset_av_ratio = 0;
    int locking_joint = -1;
};

// One [SPINDLE_n] section (rpm).
struct SpindleConfig {
    double max_pos = 1e99, min_pos = 0, max_neg = -1e99, min_neg = 0;
    double increment = 100;
};

// Everything task configures motion with, and its own settings.
struct MachineConfig {
    std::string ini_path;
    int joints = 3;
    int spindles = 1;
    int axis_mask = 7;                  // from [TRAJ]COORDINATES
    double linear_units = 1.0;          // machine units per mm
    double angular_units = 1.0;         // machine units per degree
    double default_linear_velocity = 1.0;
    double max_linear_velocity = 1e99;
    double default_linear_acceleration = 1e99;
    double max_linear_acceleration = 1e99;
    double max_linear_jerk = 1e9;
    int planner_type = 0;
    double scurve_peak_scale = 1.0;
    bool no_force_homing = false;
    bool arc_blend_enable = true, arc_blend_fallback_enable = false;
    int arc_blend_optimization_depth = 50;
    double arc_blend_gap_cycles = 4, arc_blend_ramp_freq = 100, arc_blend_kink_ratio = 0.1;
    bool no_probe_jog_error = false, no_probe_home_error = false;
    double max_feed_override = 1.0;
    double world_home[EMCMOT_MAX_AXIS] = {};
    std::vector<JointConfig> joint;
    AxisConfig axis[EMCMOT_MAX_AXIS];
    SpindleConfig spindle[EMCMOT_MAX_SPINDLES];
    // task
    double cycle_time = 0.1;            // [TASK]CYCLE_TIME s
    int interp_max_len = 1000;
    double comm_timeout = 1.0;          // [EMCMOT]COMM_TIMEOUT s
    int shmem_key = 100;                // [EMCMOT]SHMEM_KEY
    std::string io_error = "toolchanger error %d";
    // io
    std::string tool_table;             // [EMCIO]TOOL_TABLE, absolute
    bool random_toolchanger = false;
    int tool_change_axes = 0;           // [EMCIO]TOOL_CHANGE_POSITION: 0 (none), 3, 6 or 9 values
    double tool_change_position[EMCMOT_MAX_AXIS] = {};  // XYZABCUVW, machine units
    std::string program_prefix;
    std::string on_abort_command;
    std::string startup_code;
};

// Read ini into cfg. false with one message per problem in *errors ("file:line: ..." or
// "[SECTION]KEY: ...").
bool machine_config_read(const std::string &ini, MachineConfig &cfg, std::vector<std::string> *errors);
// The per-axis limits canon uses (MAX_VELOCITY/ACCELERATION less the OFFSET_AV_RATIO share).
canon_axis_limits_t machine_axis_limits(const MachineConfig &cfg);
// The canon settings of this machine (units, axes, spindles, limits, tool change position): one
// place for task and the estimator, so both plan the same moves.
struct CanonConfig;
CanonConfig machine_canon_config(const MachineConfig &cfg);

#endif
