component plasmac "Plasma cutting controller for QtPlasmaC: probing, torch start, pierce, arc voltage torch height control, pause, recovery and consumable change through external offsets";
pin out float adaptive_feed "To motion.adaptive-feed: feed factor (feed reduction, paused motion; negative runs backwards)";
pin in float arc_fail_delay "Seconds to wait for arc OK after the torch is switched on";
pin in float arc_lost_delay "Seconds arc OK may be lost while cutting before the program is paused";
pin in s32 arc_max_starts "Torch starts tried before giving up";
pin in float arc_ok_high "Mode 0: highest arc voltage counted as a valid arc";
pin in bit arc_ok_in "Modes 1 and 2: arc OK signal of the plasma source";
pin in float arc_ok_low "Mode 0: lowest arc voltage counted as a valid arc";
pin out bit arc_ok_out "Arc OK as judged for the mode";
pin in float arc_voltage_in "Raw arc voltage (modes 0 and 1)";
pin in float arc_voltage_offset "Raw reading that means 0 volts";
pin out float arc_voltage_out "Arc voltage in volts after offset, scale, low-pass and zero window";
pin in float arc_voltage_scale "Volts per raw unit";
pin in float axis_x_max_limit "X maximum limit (machine units)";
pin in float axis_x_min_limit "X minimum limit (machine units)";
pin in float axis_x_position "X position (machine units)";
pin in float axis_y_max_limit "Y maximum limit (machine units)";
pin in float axis_y_min_limit "Y minimum limit (machine units)";
pin in float axis_y_position "Y position (machine units)";
pin in float axis_z_max_limit "Z maximum limit (machine units)";
pin in float axis_z_min_limit "Z minimum limit (machine units)";
pin in float axis_z_position "Z position including the external offset (machine units)";
pin in bit breakaway "Torch breakaway switch";
pin in bit consumable_change "While paused: TRUE moves to the consumable change offset, FALSE moves back";
pin out bit consumable_changing "TRUE during a consumable change";
pin in bit cornerlock_enable "Enable the corner lock of torch height control";
pin out bit cornerlock_is_locked "TRUE while the corner lock holds torch height control";
pin in float cornerlock_threshold "Velocity in percent of the requested feed below which the corner lock sets";
pin in float creep_speed "Ramp pierce: creep speed (percent of the cut feed rate)";
pin in float creep_speed_distance "Ramp pierce: distance at creep speed";
pin out float current_feed_rate "current-velocity times 60";
pin in float current_velocity "Current tool velocity (machine units per second)";
pin in float cut_feed_rate "Cut feed rate (machine units per minute)";
pin in float cut_height "Cut height above the material";
pin in float cut_height_delay "Seconds added to the pierce delay before moving to cut height";
pin out float cut_length "Length cut in this run (machine units)";
pin out bit cut_recovering "TRUE during a cut recovery";
pin in bit cut_recovery "While paused: TRUE moves X/Y to the recovery offsets";
pin out float cut_time "Seconds cut in this run";
pin in float cut_volts "Target arc voltage when auto volts is off";
pin in bit cutting_start "Cut request (spindle.0.on)";
pin out bit cutting_stop "TRUE when a manual cut was stopped after failed starts";
pin in bit debug_print "TRUE prints the state changes (and sets the RTAPI message level to INFO)";
pin in bit dry_run "Run the program without cutting";
pin in bit external_estop "External emergency stop";
pin out bit feed_hold "To motion: hold motion while the torch is not ready";
pin in float feed_override "Feed override factor";
pin in float feed_reduction "Feed in percent of the cut feed rate while cutting (0 or 100: none)";
pin in float feed_upm "Feed rate of the current move (machine units per minute)";
pin in bit float_switch "Float switch";
pin in float float_switch_travel "Torch travel from the material until the float switch trips";
pin in float gcode_scale = 1 "G-code scale factor";
pin in float gouge_speed "Ramp pierce: gouge speed (percent of the cut feed rate)";
pin in float gouge_speed_distance "Ramp pierce: distance at gouge speed";
pin in float height_override "Height change in volts from the operator";
pin in float height_per_volt "Height change per volt of height override (machine units)";
pin in bit homed "Machine is homed";
pin in bit ignore_arc_ok_0 "Ignore arc OK (first source)";
pin in bit ignore_arc_ok_1 "Ignore arc OK (second source)";
pin out bit jog_inhibit "To motion: no jogging while a sensor is active";
pin in float kerf_width "Accepted, unused";
pin in bit laser_mode "Laser cutting: no arc needed";
pin in s32 laser_recovery_start "Laser recovery request";
pin out s32 laser_recovery_state "0 off, 1 set, 2 setting, 3 on, 4 reset, 5 resetting";
pin in s32 laser_x_offset "Laser X offset from the torch (offset counts)";
pin in s32 laser_y_offset "Laser Y offset from the torch (offset counts)";
pin out bit led_down "Torch height control moving down";
pin out bit led_up "Torch height control moving up";
pin in s32 low_cut_volts "Arc voltage below which a cut with THC active is stopped (0 = off)";
pin in float lowpass_frequency "Arc voltage low-pass cut-off frequency (Hz, 0 = off)";
pin in bit machine_is_on "Machine is on";
pin in float material_thickness "Material thickness for the first probe start height";
pin in s32 max_offset = 5 "Room kept below the Z maximum limit (mm)";
pin in bit mesh_arc_ok "Accepted, unused";
pin in bit mesh_enable "Mesh cutting: no arc OK needed, no THC";
pin in s32 mode "0 arc voltage and arc OK from it, 1 arc voltage and arc-ok-in, 2 arc-ok-in and move-up/move-down";
pin in s32 motion_type "Motion type of the current move (1 = rapid)";
pin in bit move_down "Mode 2: move the torch down";
pin in bit move_up "Mode 2: move the torch up";
pin in bit multi_tool = TRUE "Allow the scribe and spotting tools";
pin in float offset_feed_rate "Feed rate of the offset probe XY move (machine units per minute)";
pin in float offset_probe_delay "Seconds to wait for the offset probe to deploy";
pin in float offset_probe_x "X offset of the probe from the torch";
pin in float offset_probe_y "Y offset of the probe from the torch";
pin out float offset_scale "To axis.L.eoffset-scale: machine units per offset count";
pin in bit offset_set_probe "Deploy the probe (while idle)";
pin in bit offset_set_scribe "Deploy the scribe (while idle)";
pin in bit offsets_active "From motion.eoffset-active";
pin in bit offsets_limited "From motion.eoffset-limited";
pin out bit ohmic_enable "Ohmic probe circuit power";
pin in s32 ohmic_max_attempts "Failed ohmic probes before the float switch is accepted";
pin in bit ohmic_probe "Ohmic contact";
pin in bit ohmic_probe_enable "Use ohmic probing";
pin in float ohmic_probe_offset "Height of the torch above the material at ohmic contact";
pin in bit ohmic_sense_in "Raw ohmic sense input";
pin in s32 ohmic_sense_off_delay = 3 "Periods the raw ohmic sense must be FALSE to clear ohmic-sense-out";
pin in s32 ohmic_sense_on_delay = 3 "Periods the raw ohmic sense must be TRUE to set ohmic-sense-out";
pin out bit ohmic_sense_out "Debounced ohmic sense";
pin in bit ohmic_test "Ohmic test request (while idle)";
pin in s32 ok_sample_counts = 10 "Mode 0: arc voltage samples that must agree for arc OK (1..1000)";
pin in float ok_sample_threshold = 10 "Mode 0: volts within which those samples must agree";
pin in bit override_jog "Allow jogging while a sensor is active";
pin in float pause_at_end "Seconds to keep the torch on at the end of a cut";
pin out bit paused_motion "TRUE while moving along the path while paused";
pin in float paused_motion_speed "While paused: fraction of the feed to move along the path (-1..1)";
pin out float paused_time "Seconds paused in this run";
pin in float pid_d_gain "THC derivative gain";
pin in float pid_i_gain "THC integral gain (not accumulated, as LinuxCNC)";
pin in float pid_p_gain "THC proportional gain (mode 2: percent of thc-feed-rate)";
pin out s32 pierce_count "Torch starts in this run";
pin in float pierce_delay "Seconds at pierce height after arc OK";
pin in float pierce_end_height "Ramp pierce: height at the end of the pierce";
pin in float pierce_height "Pierce height above the material";
pin in float pierce_motion_delay "Pierce with motion: percent of pierce-delay before moving";
pin in s32 pierce_type "0 none, 1 wiggle, 2 ramp";
pin in float probe_feed_rate "Probe feed rate (machine units per minute)";
pin in s32 probe_final_speed = 1 "Speed feeling for the top after a contact (1..10 times resolution)";
pin out bit probe_out "float-switch AND tube-cut while idle";
pin in float probe_start_height "Probe start height above the Z minimum limit";
pin in bit probe_test "Probe test request";
pin out bit probe_test_error "TRUE after a probe test failed";
pin out float probe_time "Seconds probing in this run";
pin in bit program_is_idle "Program is idle";
pin in bit program_is_paused "Program is paused";
pin in bit program_is_running "Program is running";
pin out bit program_pause "To halui: pause the program";
pin out bit program_resume "To halui: resume the program";
pin out bit program_run "To halui: run the program";
pin out bit program_stop "To halui: stop the program";
pin in float puddle_jump_delay "Seconds at puddle jump height";
pin in float puddle_jump_height "Puddle jump height in percent of pierce height (0 or 100: none)";
pin out float rapid_time "Seconds in rapid moves in this run";
pin out float requested_feed_rate "Feed rate requested while cutting";
pin in float requested_velocity "Accepted, unused";
pin in s32 resolution = 100 "Offset counts per machine unit per second (1..1000)";
pin in float restart_delay "Seconds between a failed start and the next";
pin out float run_time "Seconds running in this run";
pin in float safe_height "Safe height above the material (0 = as high as possible)";
pin out bit safe_height_is_limited "TRUE when the safe height had to be reduced";
pin out bit scribe_arm "Scribe arm output";
pin in float scribe_arm_delay "Seconds between arming the scribe and switching it on";
pin out bit scribe_on "Scribe on output";
pin in float scribe_on_delay "Seconds after switching the scribe on before motion is released";
pin in bit scribe_start "Scribe request (spindle.1.on)";
pin out bit sensor_active "breakaway, float switch or ohmic contact active";
pin in float setup_feed_rate "Feed rate of torch height moves (machine units per minute)";
pin in float skip_ihs_distance "Cuts starting closer than this to the previous one are not probed";
pin in float slat_height "Slat height for the first probe start height";
pin in bit spotting_start "Spotting request (spindle.2.on)";
pin in float spotting_threshold "Arc voltage that starts the spotting timer";
pin in float spotting_time "Milliseconds the torch stays on after the spotting threshold";
pin out s32 state_out "State (see the description)";
pin out s32 stop_type_out "0 none, 1 stop, 2 wait, 3 pause";
pin in s32 target_samples = 6 "Samples averaged for the auto volts target";
pin out float target_volts "Target arc voltage of THC";
pin out bit thc_active "TRUE while THC moves the torch";
pin in bit thc_auto "Take the target voltage as soon as the arc is steady";
pin in float thc_delay "Seconds after reaching cut height before THC starts";
pin in bit thc_disable "Disable THC (from the program)";
pin in bit thc_enable "Enable THC (from the operator)";
pin out bit thc_enabled "THC allowed";
pin in float thc_feed_rate "Largest THC speed (machine units per minute)";
pin in s32 thc_sample_counts = 50 "THC auto samples (1..1000)";
pin in float thc_sample_threshold = 1 "Volts within which the THC auto samples must agree";
pin in float thc_threshold "Voltage error below which THC does not move";
pin in bit torch_enable "Allow the torch to be switched on";
pin in bit torch_off "Switch the torch off";
pin out bit torch_on "Torch on output";
pin in bit torch_pulse_abort "End a torch pulse";
pin in bit torch_pulse_hold "Keep a torch pulse on";
pin in bit torch_pulse_start "Start a torch pulse (while idle)";
pin in float torch_pulse_time "Seconds of a torch pulse";
pin out float torch_time "Seconds with the torch on in this run";
pin in bit tube_cut "Tube cutting: no probing";
pin in float units_per_mm "Machine units per millimetre";
pin in bit use_auto_volts "Take the target voltage from the arc";
pin in bit voidlock_enable "Enable the void lock of THC";
pin out bit voidlock_is_locked "TRUE while the void lock holds THC";
pin in s32 voidlock_off_cycles = 10 "Periods that release the void lock";
pin in s32 voidlock_on_cycles = 2 "Periods of steep voltage change that set the void lock";
pin in s32 voidlock_slope = 500 "Arc voltage slope (volts per second) counted toward the void lock";
pin in s32 x_offset "Consumable change X offset (offset counts)";
pin out s32 x_offset_counts "To axis.x.eoffset-counts";
pin in float x_offset_current "From axis.x.eoffset";
pin in float xy_feed_rate "Feed rate of consumable change moves (machine units per minute)";
pin out bit xy_offset_enable "To axis.x/y.eoffset-enable";
pin in s32 y_offset "Consumable change Y offset (offset counts)";
pin out s32 y_offset_counts "To axis.y.eoffset-counts";
pin in float y_offset_current "From axis.y.eoffset";
pin out float z_height "Torch height above the material (or the Z minimum limit before probing)";
pin out s32 z_offset_counts "To axis.z.eoffset-counts";
pin in float z_offset_current "From axis.z.eoffset";
pin out bit z_offset_enable "To axis.z.eoffset-enable";
pin out float z_relative "Not written (LinuxCNC compatibility)";
pin in float zero_window = 0.1 "Volts around 0 read as 0";
variable double offset_res;
variable double vs;
variable double raw_volts;
variable double ring[1000];
variable int ring_idx;
variable int ring_n;
variable double lost_timer;
variable double fail_timer;
variable double restart_timer;
variable double timer;
variable double spot_timer;
variable double thc_timer;
variable double bad_volts_timer;
variable double zero;
variable int has_zero;
variable int probe_required = 1;
variable int first_cut = 1;
variable int probe_start;
variable int cut_t;
variable int pierce_t;
variable int pierce_end_t;
variable int puddle_t;
variable int safe_t;
variable int top_t;
variable int bottom_t;
variable int x_target;
variable int y_target;
variable double start_x;
variable double start_y;
variable double end_x;
variable double end_y;
variable int thc_was_active;
variable double e_prev;
variable double v_prev;
variable double override_prev;
variable double auto_sum;
variable int auto_n;
variable double pierce_dist;
variable double pierce_px;
variable double pierce_py;
variable int starts;
variable int ohmic_tries;
variable int probe_type;
variable int probe_retry;
variable int probe_inhibit;
variable int cut_started;
variable int job;
variable int stats_done;
variable int limit_latched;
variable int no_arc_told;
variable int ohmic_on_n;
variable int ohmic_off_n;
variable int void_on_n;
variable int void_off_n;
variable int recovering;
variable int cc_blocked;
variable int spot_started;
variable int scribe_phase;
variable int pulse_recovery;
variable int offset_probing;
variable int last_state;
variable int tool;
variable int laser_x;
variable int laser_y;
variable int deploy;
variable int safe_base;
variable int ovr_target;
variable int ovr_moving;
function _ "Run plasmac (floating point)";
option singleton yes;
include <rtapi_math.h>;
include "plasmac_defs.h";
license "GPL";
author "OpenEMC";
description """LinuxCNC's plasmac (component version 016), the controller behind QtPlasmaC. It
drives motion's external offsets: wire offset-scale to axis.L.eoffset-scale and
x/y/z-offset-counts to axis.L.eoffset-counts; x/y/z-offset-current come from axis.L.eoffset.
Offsets are counted in units of offset-scale = units-per-mm * period / resolution machine
units; a feed rate F (units per minute) moves F * resolution / units-per-mm / 60 counts per
period.

state-out: 0 IDLE, 1 PROBE_HEIGHT, 2 PROBE_DOWN, 3 PROBE_UP, 4 ZERO_HEIGHT, 5 PIERCE_HEIGHT,
6 TORCH_ON, 7 ARC_OK, 8 PIERCE_DELAY, 9 PUDDLE_JUMP, 10 CUT_HEIGHT, 11 CUT_MODE_01, 12 CUT_MODE_2,
13 PAUSE_AT_END, 14 SAFE_HEIGHT, 15 MAX_HEIGHT, 16 END_CUT, 17 END_JOB, 18 TORCHPULSE,
19 PAUSED_MOTION, 20 OHMIC_TEST, 21 PROBE_TEST, 22 SCRIBING, 23 CONSUMABLE_CHANGE_ON,
24 CONSUMABLE_CHANGE_OFF, 25 CUT_RECOVERY_ON, 26 CUT_RECOVERY_OFF, 27 DEBUG.
stop-type-out: 0 none, 1 stop, 2 wait (M5 between cuts), 3 pause.

A cut (spindle.0.on on cutting-start, not a dry run) probes the material (float switch or
ohmic contact), moves to pierce height, starts the torch (arc-max-starts tries of
arc-fail-delay seconds, restart-delay apart), waits pierce-delay (pierce with motion: wiggle or
ramp), optionally jumps the puddle, goes to cut height and controls the height by arc voltage
(modes 0 and 1: P, I and D gains, corner lock, void lock, height override, auto volts) or by
move-up/move-down (mode 2). Mode 0 derives arc OK from the voltage, modes 1 and 2 take arc-ok-in.
A breakaway, a float switch or ohmic contact, a lost arc, an offset limit, a probe reaching the
bottom or an arc voltage below low-cut-volts switch the torch off, pause the program and raise the
torch (MAX_HEIGHT); each is reported. At the end of a cut the torch goes to the safe height (or
the top). While paused the operator can change consumables (x-offset, y-offset), recover a cut
(cut-recovery, laser-recovery-start) or move along the path (paused-motion-speed). Scribe and
spotting tools run with multi-tool. Statistics (cut length and times, pierce count) are reset
when a program starts running.

With debug-print TRUE every state change is printed, and the RTAPI message level is set to INFO
(1, errors only, while FALSE) on every period, as LinuxCNC's plasmac does. An infinite or NaN
arc-voltage-in is reported once a second and stops plasmac until it is valid again.""";
;;
#include "hal/components/plasmac_io.h"
#include "hal/components/plasmac_move.h"
#include "hal/components/plasmac_abort.h"
#include "hal/components/plasmac_probe.h"
#include "hal/components/plasmac_cut.h"
#include "hal/components/plasmac_thc.h"
#include "hal/components/plasmac_end.h"
#include "hal/components/plasmac_pause.h"
#include "hal/components/plasmac_cycle.h"

/* One period: LinuxCNC's per-call sequence, then the state machine. */
FUNCTION(_)
{
    double t = fperiod;
    if (!pm_before(__comp_inst, t)) return;
    if (!machine_is_on) {
        pm_machine_off(__comp_inst);
    } else {
        pm_run_state(__comp_inst, t);
    }
    pm_after(__comp_inst);
}
