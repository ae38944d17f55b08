// halui.hh: halui's configuration, HAL pins and state, and the functions of its per-cycle work.
#ifndef HALUI_HH
#define HALUI_HH

#include <string>
#include <vector>

#include "hal.h"
#include "halui_override.hh"
#include "ui_client.hh"

// Most [HALUI]MDI_COMMAND entries halui exports (LinuxCNC's limit).
constexpr int HALUI_MAX_MDI = 64;
// Soft keys of the GUI bridge (halui.gui.softkey.00 .. 19).
constexpr int HALUI_GUI_SOFTKEYS = 20;
// Axis letters in index order.
extern const char HALUI_AXIS_LETTERS[EMCMOT_MAX_AXIS + 1];

// What halui reads from the INI file.
struct HaluiConfig {
    std::string ini_path;
    std::string nml_file;
    int joints = 0;
    int spindles = 1;
    unsigned axis_mask = 0;             // bit i: axis HALUI_AXIS_LETTERS[i] exists
    bool home_sequence = false;         // some [JOINT_n]HOME_SEQUENCE is set: halui.home-all
    double units_per_mm = 1.0;          // [TRAJ]LINEAR_UNITS
    double max_feed_override = 1.0;     // [DISPLAY]MAX_FEED_OVERRIDE
    double max_rapid_override = 1.0;    // [DISPLAY]MAX_RAPID_OVERRIDE
    double min_spindle_override = 0.0;  // [DISPLAY]MIN_SPINDLE_OVERRIDE
    double max_spindle_override = 1.0;  // [DISPLAY]MAX_SPINDLE_OVERRIDE
    double max_velocity = 1e99;         // [TRAJ]MAX_LINEAR_VELOCITY
    double default_spindle_speed = 0;   // [DISPLAY]DEFAULT_SPINDLE_SPEED (0: LinuxCNC's 500 rpm)
    std::vector<std::string> mdi_commands;   // [HALUI]MDI_COMMAND, in order
    std::vector<std::string> gui_mdi_names;  // halui.gui.mdi-command.<name> pins
};

// Read the configuration; false with a message on stderr naming file, line and problem.
bool halui_read_config(const std::string &ini_path, HaluiConfig &cfg);

// ---- pins

// An input bit whose changes are seen once: edge() is +1 on a rising, -1 on a falling edge.
struct BitIn {
    hal_bit_t **ref = nullptr;
    bool last = false;
    int edge()
    {
        bool v = **ref;
        int e = v == last ? 0 : (v ? 1 : -1);
        last = v;
        return e;
    }
    bool rose() { return edge() > 0; }
    bool value() const { return **ref; }
};

struct OverridePins {
    hal_bit_t **count_enable, **direct_value, **increase, **decrease, **reset;
    hal_s32_t **counts;
    hal_float_t **scale, **value;
};

// Jog controls of one joint or axis (analog is absent for the selected ones).
struct JogPins {
    BitIn plus, minus, increment_plus, increment_minus;
    hal_float_t **increment = nullptr, **analog = nullptr;
};

// Status of one joint (also used for halui.joint.selected.*).
struct JointStatusPins {
    hal_bit_t **is_homed, **has_fault, **on_soft_min, **on_soft_max, **on_hard_min,
        **on_hard_max, **override_limits;
};

struct JointPins {
    BitIn select, home, unhome;
    JogPins jog;
    hal_bit_t **is_selected;
    JointStatusPins status;
};

struct AxisPins {
    BitIn select;
    JogPins jog;
    hal_bit_t **is_selected;
    hal_float_t **pos_commanded, **pos_feedback, **pos_relative;
};

struct SpindlePins {
    BitIn start, stop, forward, reverse, increase, decrease, brake_on, brake_off;
    hal_bit_t **is_on, **runs_forward, **runs_backward, **brake_is_on;
    OverridePins override;
};

struct GuiPins {
    hal_bit_t **cycle_start, **cycle_pause, **response_ok, **response_cancel, **reload_preview,
        **shutdown;
    hal_bit_t **softkey[HALUI_GUI_SOFTKEYS];
    std::vector<hal_bit_t **> mdi_command;
    hal_float_t **jog_rate, **jog_rate_angular;
};

// Every pin halui owns. Buttons (BitIn) act on edges; the plain refs are levels or outputs.
struct HaluiPins {
    BitIn machine_on, machine_off, estop_activate, estop_reset;
    BitIn mode_manual, mode_auto, mode_mdi, mode_teleop, mode_joint;
    BitIn mist_on, mist_off, flood_on, flood_off;
    BitIn program_run, program_pause, program_resume, program_step, program_stop;
    BitIn optional_stop_on, optional_stop_off, block_delete_on, block_delete_off;
    BitIn abort, home_all;  // home_all.ref is null without a homing sequence
    hal_bit_t **machine_is_on, **estop_is_activated;
    hal_bit_t **mode_is_manual, **mode_is_auto, **mode_is_mdi, **mode_is_teleop, **mode_is_joint;
    hal_bit_t **mist_is_on, **flood_is_on;
    hal_bit_t **program_is_idle, **program_is_running, **program_is_paused;
    hal_bit_t **optional_stop_is_on, **block_delete_is_on;
    hal_float_t **units_per_mm;

    OverridePins feed_override, rapid_override, max_velocity;
    SpindlePins spindle[EMCMOT_MAX_SPINDLES];

    JointPins joint[EMCMOT_MAX_JOINTS];
    BitIn joint_selected_home, joint_selected_unhome;
    JogPins joint_selected_jog;
    JointStatusPins joint_selected_status;
    hal_u32_t **joint_selected;
    hal_float_t **joint_jog_speed, **joint_jog_deadband;

    AxisPins axis[EMCMOT_MAX_AXIS];
    JogPins axis_selected_jog;
    hal_u32_t **axis_selected;
    hal_float_t **axis_jog_speed, **axis_jog_speed_angular, **axis_jog_deadband;

    hal_u32_t **tool_number;
    hal_float_t **tool_length_offset[EMCMOT_MAX_AXIS];
    hal_float_t **tool_diameter;

    std::vector<BitIn> mdi_command;
    hal_bit_t **mdi_is_running = nullptr;  // only with MDI commands

    GuiPins gui;
};

// Create every pin; 0 or a negative errno (a message names the pin).
int halui_make_pins(int comp_id, const HaluiConfig &cfg, HaluiPins &pins);
// Create the halui.gui.* pins of the GUI bridge.
int halui_make_gui_pins(int comp_id, const HaluiConfig &cfg, GuiPins &pins);

// ---- state

// Where a jog target's analog input stands (its last commanded multiplier).
struct AnalogJog {
    double last = 0;
};

// The GUI bridge's jog-rate arbitration.
struct GuiJogRate {
    bool bridge_seen = false;
    double last_halui = 0, last_bridge = 0;
    double rate = 0;
    bool bridge_won = false;
    double last_halui_ang = 0, last_bridge_ang = 0;
    double rate_ang = 0;
    bool bridge_won_ang = false;
};

struct Halui {
    explicit Halui(const HaluiConfig &c) : cfg(c), client(c.nml_file) {}
    HaluiConfig cfg;
    UiClient client;
    HaluiPins pins{};
    int selected_joint = 0;
    int selected_axis = 0;
    AnalogJog joint_analog[EMCMOT_MAX_JOINTS];
    AnalogJog axis_analog[EMCMOT_MAX_AXIS];
    OverrideKnob feed_knob, rapid_knob, maxvel_knob, spindle_knob[EMCMOT_MAX_SPINDLES];
    // MDI commands sent from halui.mdi-command-NN
    bool mdi_running = false;
    int32_t mdi_serial = 0;   // serial of the last one
    int mdi_saved_mode = 0;   // mode to return to once they are done (0: none)
    GuiJogRate gui_rate;
    bool warned_no_machine = false;
};

// Send a command and wait until task has read it; false when it could not be sent.
bool halui_send(Halui &h, const NMLmsg &msg);
// True when task runs and reports a status.
bool halui_machine_ready(Halui &h);

// One cycle of each part, in this order: buttons (state, mode, program, coolant, abort,
// home-all), spindles, overrides, the GUI bridge's jog rates, joint/axis selection with
// homing and jogging, MDI commands, then the outputs.
void halui_buttons(Halui &h);
void halui_spindles(Halui &h);
void halui_overrides(Halui &h, double now_s);
void halui_jogging(Halui &h);
void halui_mdi(Halui &h);
void halui_gui(Halui &h);
void halui_outputs(Halui &h);

// The jog speed halui uses for axis i (linear, angular for A/B/C), after the GUI bridge.
double halui_axis_jog_speed(const Halui &h, int axis);

#endif
