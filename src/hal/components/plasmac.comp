component plasmac "Plasma cutting controller: torch height, arc supervision and torch height control through external offsets";
pin in float arc_fail_delay = 3.0 "Seconds to wait for a valid arc after the torch is switched on";
pin in s32 arc_max_starts = 3 "Torch starts tried before an arc failure pauses the program";
pin in bit arc_ok_in "Arc OK input from the plasma source (modes 1 and 2)";
pin in float arc_ok_high = 250.0 "Arc voltage above which the arc is not OK (mode 0)";
pin in float arc_ok_low = 60.0 "Arc voltage below which the arc is not OK (mode 0)";
pin in float arc_restart_delay = 1.0 "Seconds between a failed start and the next torch start";
pin in float arc_voltage_in "Raw arc voltage sensor value (modes 0 and 1)";
pin in float arc_voltage_offset "Raw sensor value that reads as 0 volts";
pin in float arc_voltage_scale = 1.0 "Volts per raw sensor unit";
pin in float axis_x_max_limit "X axis maximum limit (machine units)";
pin in float axis_x_min_limit "X axis minimum limit (machine units)";
pin in float axis_x_position "Current X position, used for cut length and skip-IHS distance";
pin in float axis_y_max_limit "Y axis maximum limit (machine units)";
pin in float axis_y_min_limit "Y axis minimum limit (machine units)";
pin in float axis_y_position "Current Y position, used for cut length and skip-IHS distance";
pin in float axis_z_max_limit "Z axis maximum limit (machine units)";
pin in float axis_z_min_limit "Z axis minimum limit (machine units); probing stops there";
pin in float axis_z_position "Current Z position including the offset this component applies";
pin in bit breakaway "Torch breakaway switch; TRUE during a cut pauses the program";
pin in bit consumable_change "While paused: TRUE moves to the consumable change offset, FALSE moves back";
pin in bit cornerlock_enable "Hold torch height control while the machine runs slower than the threshold";
pin in float cornerlock_threshold = 90.0 "Corner lock threshold in percent of the cut feed rate";
pin in float current_velocity "Current tool velocity (machine units per second)";
pin in float cut_feed_rate "Cut feed rate of the material (machine units per minute)";
pin in float cut_height "Torch height while cutting (machine units)";
pin in bit cutting_start "Cut request (spindle on): a rising edge starts a cut, FALSE ends it";
pin in bit cutting_stop "TRUE ends the current cut like a falling cutting-start";
pin in float cut_volts "Target arc voltage for torch height control when auto volts is off";
pin in float feed_override = 1.0 "Feed override factor (1.0 = 100%)";
pin in float feed_reduction "Percentage (1 to 99) of the cut feed rate while cutting; 0 or 100 = full speed";
pin in bit float_switch "Float switch: ends a probe; TRUE during a cut pauses the program";
pin in float float_switch_travel "Torch travel from touching the material until the float switch trips";
pin in float height_override "Height change in volts requested by the operator";
pin in float height_per_volt = 0.1 "Torch height change per arc volt (machine units)";
pin in bit ignore_arc_ok_0 "Do not need or supervise a valid arc (for example when marking)";
pin in bit ignore_arc_ok_1 "Do not need or supervise a valid arc, second source";
pin in bit kerfcross_enable "Hold torch height control while the arc voltage rises like when crossing a kerf";
pin in float kerfcross_override = 100.0 "Kerf crossing rate threshold in percent of 1000 volts per second";
pin in bit machine_is_on "Machine on; FALSE stops everything and clears the offsets";
pin in float max_offset "Largest height correction from cut height (machine units); 0 = no limit";
pin in s32 mode "0: arc OK and height control from arc voltage; 1: arc OK from arc-ok-in, height from arc voltage; 2: arc OK from arc-ok-in, height from move-up/move-down";
pin in s32 motion_type "Motion type of the current move; height control runs only for feed (2) and arc (3) moves";
pin in bit move_down "Mode 2: move the torch down while cutting";
pin in bit move_up "Mode 2: move the torch up while cutting";
pin in bit ohmic_probe "Ohmic contact sense input";
pin in bit ohmic_probe_enable "Use the ohmic contact as well as the float switch to find the material";
pin in float ohmic_probe_offset "Distance added to the Z of an ohmic contact to get the material surface";
pin in float paused_motion_speed "While paused: run along the path with the torch off at this fraction of the feed (-1 to 1, negative runs backwards); 0 pauses again";
pin in float pid_d_gain "Derivative gain of the arc voltage loop (percent of thc-feed-rate per volt per second)";
pin in float pid_i_gain "Integral gain of the arc voltage loop (percent of thc-feed-rate per volt second)";
pin in float pid_p_gain = 10.0 "Proportional gain of the arc voltage loop (percent of thc-feed-rate per volt)";
pin in float pierce_delay "Seconds to wait at pierce height after the arc is OK";
pin in float pierce_height "Torch height for piercing (machine units)";
pin in float probe_feed_rate "Feed rate of the slow probe (machine units per minute)";
pin in float probe_start_height "Height above the Z minimum limit where the slow probe starts";
pin in bit probe_test "While idle, a rising edge probes the material and holds the torch at pierce height until FALSE";
pin in bit program_is_idle "Program is idle (stopped)";
pin in bit program_is_paused "Program is paused";
pin in bit program_is_running "Program is running";
pin in float puddle_jump_delay "Seconds at puddle jump height after the pierce delay";
pin in float puddle_jump_height "Puddle jump height in percent of pierce height; 0 = no puddle jump";
pin in float requested_velocity "Requested tool velocity (machine units per second); corner lock reference when cut-feed-rate is 0";
pin in bit out_of_limits "TRUE when the program would leave the machine limits; a cut start then stops the program";
pin in float safe_height "Torch height between cuts (machine units)";
pin in float setup_feed_rate "Feed rate of torch height moves other than probing (machine units per minute)";
pin in float skip_ihs_distance "A cut starting closer than this to the end of the previous cut is not probed; 0 = always probe";
pin in float thc_delay "Seconds after reaching cut height before torch height control starts";
pin in bit thc_disable "Disable torch height control (from the program)";
pin in bit thc_enable "Enable torch height control (from the operator)";
pin in float thc_feed_rate "Largest torch height control velocity (machine units per minute)";
pin in s32 thc_sample_counts = 50 "Cycles of arc voltage averaged for the target voltage when auto volts is on";
pin in float thc_threshold = 1.0 "Voltage error below which the height is not corrected";
pin in bit torch_enable "Allow the torch to be switched on; FALSE runs programs without cutting";
pin in bit torch_pulse_start "While idle, a rising edge switches the torch on for torch-pulse-time";
pin in float torch_pulse_time "Seconds the torch is on for a torch pulse";
pin in float units_per_mm = 1.0 "Machine units per millimetre (1 for metric machines, 1/25.4 for inch machines)";
pin in bit use_auto_volts "Take the target voltage from the arc at the end of thc-delay instead of cut-volts";
pin in float x_offset "X offset of the consumable change position (machine units)";
pin in float xy_feed_rate "Feed rate of consumable change moves (machine units per minute)";
pin in float y_offset "Y offset of the consumable change position (machine units)";
pin in float arc_lost_delay "Seconds a lost arc is tolerated while cutting before the program is paused";
pin in bit cut_recovery "While paused: TRUE moves X/Y to x-offset, y-offset and keeps them there for the restarted cut";
pin in s32 cut_type "0: normal cut; 1: pierce only (the torch goes off after the pierce delay)";
pin in bit debug_print "Accepted for HAL file compatibility; this component never prints from the realtime cycle";
pin in bit external_estop "External emergency stop: torch and scribe off, program stop, offsets back to 0";
pin in bit laser_recovery_start "While paused: TRUE moves X/Y by laser-x-offset, laser-y-offset; FALSE moves back";
pin in float laser_x_offset "X distance of the alignment laser from the torch (machine units)";
pin in float laser_y_offset "Y distance of the alignment laser from the torch (machine units)";
pin in bit mesh_enable "Mesh mode: no arc OK needed or supervised and no height control";
pin in bit multi_tool "Allow the scribe (scribe-start) and spotting (spotting-start) tools";
pin in float offset_probe_delay "Seconds to wait at the probe offset position before probing";
pin in float offset_probe_x "X offset moved before probing when the probe is not at the torch (machine units)";
pin in float offset_probe_y "Y offset moved before probing when the probe is not at the torch (machine units)";
pin in bit offset_set_probe "While idle, a rising edge probes without the probe offset and holds at pierce height until FALSE";
pin in bit offset_set_scribe "While idle, TRUE arms and then fires the scribe (to mark the material) until FALSE";
pin in bit offsets_active "External offsets still applied by motion; returns to idle wait until FALSE";
pin in s32 ohmic_max_attempts "Probes retried when the float switch trips without an ohmic contact; then the float switch is used";
pin in bit ohmic_test "While idle, TRUE powers the ohmic contact circuit (ohmic-enable) for a test";
pin in float scribe_arm_delay "Seconds between arming the scribe and switching it on";
pin in float scribe_on_delay "Seconds after switching the scribe on before motion is released";
pin in bit scribe_start "Scribe request (spindle 1 on) with multi-tool: a rising edge starts scribing, FALSE ends it";
pin in bit spotting_start "Spotting request (spindle 2 on) with multi-tool: a rising edge probes and fires a spot";
pin in float spotting_threshold "Arc voltage that starts the spotting timer; 0 starts it when the torch switches on";
pin in float spotting_time "Milliseconds the torch stays on after the spotting threshold is reached";
pin in float thc_sample_threshold "Auto volts samples count only while the voltage changes less than this per cycle; 0 = always";
pin in bit torch_off "TRUE switches the torch off and ends the cut; no cut or torch pulse starts while TRUE";
pin in bit voidlock_enable "Hold torch height control while the arc voltage rises steeply (voids, kerf crossings)";
pin in s32 voidlock_off_cycles = 10 "Cycles within thc-threshold of the target that release the void lock";
pin in s32 voidlock_on_cycles = 2 "Consecutive cycles above voidlock-slope that set the void lock";
pin in float voidlock_slope = 500.0 "Arc voltage rise in volts per second that counts toward the void lock";
pin in float zero_window "arc-voltage-out reads 0 while the arc voltage is within this many volts of 0";
pin out float adaptive_feed = 1.0 "Adaptive feed factor for motion (feed reduction)";
pin out bit arc_ok_out "Arc OK as judged from the source selected by mode";
pin out float arc_voltage_out "Arc voltage in volts";
pin out bit cornerlock_is_locked "Height control held by the corner lock";
pin out float cut_length "Total length cut with a valid arc (machine units)";
pin out float cut_time "Total time cut with a valid arc (seconds)";
pin out s32 error_out "Last fault: 0 none, 1 breakaway, 2 float switch, 3 probe reached the Z minimum limit, 4 no arc after arc-max-starts starts, 5 arc lost while cutting, 6 out of limits, 7 float switch active before probing, 8 external estop";
pin out bit feed_hold "TRUE holds motion until the torch is at cut height";
pin out bit kerfcross_is_locked "Height control held by the kerf crossing detection";
pin out bit led_down "Height control is moving the torch down";
pin out bit led_up "Height control is moving the torch up";
pin out float offset_scale "Machine units per offset count, for axis.N.eoffset-scale";
pin out bit ohmic_enable "Power the ohmic contact circuit (while probing with ohmic-probe-enable)";
pin out s32 pierce_count "Number of successful pierces";
pin out bit probe_test_error "The last probe test did not find the material";
pin out bit program_pause "Pause request for the program (held until the program is paused)";
pin out bit program_resume "Resume request for paused motion (held until the program runs)";
pin out bit program_stop "Stop request for the program (held until the program is idle)";
pin out s32 state_out "Current state (see the description)";
pin out s32 stop_type_out "Action after the torch reached a safe position: 0 none, 1 stop, 2 pause";
pin out bit thc_active "Height control is correcting the torch height";
pin out bit thc_enabled "Height control is enabled (thc-enable and not thc-disable)";
pin out bit torch_on "Switch the plasma torch on";
pin out s32 x_offset_counts "X external offset in counts of offset-scale";
pin out bit xy_offset_enable "Enable for the X and Y external offsets";
pin out s32 y_offset_counts "Y external offset in counts of offset-scale";
pin out float z_height "Torch height above the material once it has been found (machine units)";
pin out s32 z_offset_counts "Z external offset in counts of offset-scale";
pin out bit z_offset_enable "Enable for the Z external offset";
pin out s32 laser_recovery_state "0 none, 1 moving to the laser position, 2 at the laser position, 3 moving back";
pin out bit scribe_arm "Arm (lower) the scribe";
pin out bit scribe_on "Switch the scribe on";
pin out bit voidlock_is_locked "Height control held by the void lock";
pin out float x_offset_current "X external offset now applied (machine units)";
pin out float y_offset_current "Y external offset now applied (machine units)";
pin out float z_offset_current "Z external offset now applied (machine units)";
variable int state;
variable double zoff;
variable double xoff;
variable double yoff;
variable double zbase;
variable double zzero;
variable int have_zero;
variable double zcontact;
variable int contact_float;
variable double timer;
variable int starts;
variable double end_x;
variable double end_y;
variable double prev_x;
variable double prev_y;
variable double volts;
variable double prev_volts;
variable double volts_target;
variable double volts_sum;
variable int volts_n;
variable double pid_int;
variable double pid_prev;
variable int arc_ok_now;
variable int last_start;
variable int last_probe_test;
variable int last_pulse;
variable int probe_testing;
variable int seen_paused;
variable int tool;
variable int ohmic_tries;
variable double lost_timer;
variable int spot_armed;
variable double probe_x0;
variable double probe_y0;
variable int probe_offset_used;
variable int void_on;
variable int void_off;
variable int last_scribe;
variable int last_spot;
variable int last_set_probe;
function _;
description """A torch height and cut sequence controller for plasma tables, in the
style of QtPlasmaC. All Z motion is made through external offsets: the component
moves its own offset at the feed rate of each step and writes it to
z-offset-counts (and X/Y for the consumable change) in counts of offset-scale,
which is 0.001 mm expressed in machine units (0.001 * units-per-mm). A feed rate
of 0 makes the move in one cycle.

A cut starts on a rising edge of cutting-start (spindle on) while the machine is on
and the torch is enabled. The states (state-out) are:

  0 IDLE           waiting for a cut, a probe test or a torch pulse
  1 PROBE_HEIGHT   fast down to probe-start-height above Z minimum
  2 PROBE_DOWN     slow down until float switch or ohmic contact
  3 PROBE_UP       slow up until the float switch opens again
  4 ZERO_HEIGHT    material surface recorded
  5 PIERCE_HEIGHT  move to pierce-height
  6 TORCH_ON       torch on (after arc-restart-delay on a restart)
  7 ARC_OK         waiting up to arc-fail-delay for a valid arc
  8 PIERCE_DELAY   waiting pierce-delay
  9 PUDDLE_JUMP    at puddle-jump-height percent of pierce height
 10 CUT_HEIGHT     move to cut-height, then feed-hold is released
 11 CUT_MODE_01    cutting, arc voltage height control (modes 0, 1)
 12 CUT_MODE_2     cutting, move-up/move-down control (mode 2)
 13 END_CUT        torch off at the end of a cut
 14 SAFE_HEIGHT    move to safe-height above the material
 15 MAX_HEIGHT     offset back to 0 (the programmed Z)
 16 TORCH_PULSE    torch on for torch-pulse-time
 17 PAUSED         paused by a fault or the operator
 18 PROBE_TEST     holding at pierce height after a probe test
 19 CONSUMABLE_CHANGE_ON   X/Y moving to x-offset, y-offset
 20 CONSUMABLE_CHANGE_OFF  X/Y moving back
 21 PAUSED_MOTION  running at paused-motion-speed, torch off
 22 SCRIBE_ARM     scribe armed for scribe-arm-delay
 23 SCRIBE_ON      scribe on, waiting scribe-on-delay
 24 SCRIBING       motion runs with the scribe on
 25 SPOTTING       torch on for a spot
 26 OHMIC_RETRY    float switch without ohmic contact: up until it opens, probe again
 27 OFFSET_PROBE   X/Y moving to the probe offset, then waiting offset-probe-delay
 28 OFFSET_RETURN  X/Y moving back from the probe offset
 29 RECOVER_RETURN cutting from a cut recovery offset back onto the path
 30 CUT_RECOVERY   paused, X/Y following x-offset, y-offset
 31 LASER_RECOVERY paused, X/Y at the laser offsets and back

The surface is the Z where the float switch opened plus
float-switch-travel, or the Z of the ohmic contact plus ohmic-probe-offset.

When no arc is seen within arc-fail-delay the torch is switched off, and after
arc-restart-delay switched on again; after arc-max-starts failed starts the program is
paused (error-out 4). Resuming the paused program restarts the cut from probing.
A breakaway during a cut, a float switch during piercing or cutting or a lost arc
(unless ignore-arc-ok-0/1) switches the torch off, requests a pause and raises the
torch to the programmed Z. A probe that reaches the Z minimum limit, or a start
while out-of-limits is TRUE, requests a program stop; probing needs
axis-z-min-limit below axis-z-max-limit. Stopping the program or the
end of the cut switches the torch off.
While paused, consumable-change moves X/Y to the change offset and back, and a
non-zero paused-motion-speed requests a resume with adaptive-feed set to that
speed and the torch off; setting it back to 0 requests a pause again.

With multi-tool TRUE, a rising scribe-start arms the scribe (scribe-arm), switches it
on (scribe-on) after scribe-arm-delay and releases motion after scribe-on-delay; it
ends when scribe-start falls. offset-set-scribe does the same while the program is
idle. A rising spotting-start probes like a cut, moves to pierce height and
switches the torch on; once the arc voltage reaches spotting-threshold the torch
stays on for spotting-time milliseconds. cut-type 1 pierces only: the torch goes
off after the pierce delay. torch-off TRUE ends a cut with the torch off (no pause)
and blocks cuts, spots and torch pulses. mesh-enable cuts without arc OK and without
height control. external-estop switches torch and scribe off, requests a program
stop (error 8), returns all offsets to 0 and blocks every start while TRUE.

When offset-probe-x or offset-probe-y is not 0, X/Y move by them at xy-feed-rate
before probing, wait offset-probe-delay and move back after the surface is found;
offset-set-probe runs a probe test without that move. With ohmic-probe-enable, a
float switch trip without ohmic contact rises until the switch opens and probes
again, at most ohmic-max-attempts times, then the float switch is used. ohmic-test
powers ohmic-enable while idle. While paused, cut-recovery moves X/Y to x-offset,
y-offset and keeps them there: the resumed cut starts at that point and moves back
to the path at cut-feed-rate before motion is released; laser-recovery-start moves
X/Y to laser-x-offset, laser-y-offset and back (laser-recovery-state). Returns to
IDLE or PAUSED after MAX_HEIGHT or a consumable change wait until offsets-active
is FALSE. x/y/z-offset-current show the offsets applied. A lost arc pauses only
after arc-lost-delay seconds. debug-print is accepted and has no effect.
arc-voltage-out reads 0 within zero-window volts of 0.

Height control (CUT_MODE_01) starts thc-delay seconds after cut height is reached,
when thc-enable is TRUE and thc-disable FALSE. The target is cut-volts, or with
use-auto-volts the mean of thc-sample-counts cycles of arc voltage taken after
thc-delay, plus height-override. When the voltage differs from the target by more
than thc-threshold, the torch moves at a velocity of thc-feed-rate times the PID
output in percent (clamped to 100): up when the voltage is low, down when it is
high. It holds while motion-type is not a feed or arc move, while the corner lock
(velocity below cornerlock-threshold percent of cut-feed-rate times feed-override)
or the kerf crossing lock (voltage rising faster than kerfcross-override percent of
1000 V/s, released when the voltage is back within thc-threshold of the target) or
the void lock (voidlock-on-cycles cycles rising faster than voidlock-slope volts per
second, released after voidlock-off-cycles cycles within thc-threshold of the target)
is on. Auto volts samples count only while the voltage changes by at most
thc-sample-threshold per cycle (when it is above 0). Without height control the torch stays at cut-height plus height-override times
height-per-volt. The correction stays within max-offset of cut height and the Z limits.""";
option singleton yes;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
#include "hal/components/plasmac_motion.h"
#include "hal/components/plasmac_thc.h"
#include "hal/components/plasmac_states.h"
#include "hal/components/plasmac_tools.h"
#include "hal/components/plasmac_recovery.h"
#include "hal/components/plasmac_faults.h"

/* One cycle: sense the arc, let faults override the state, run its handler, write outputs. */
FUNCTION(_)
{
    plasmac_sense(__comp_inst);
    if (!plasmac_faults(__comp_inst, fperiod))
        plasmac_handlers[state](__comp_inst, fperiod);
    plasmac_outputs(__comp_inst);
}
