component spindle_monitor "Spindle at-speed and under-speed from command and feedback";
description """
\\fBlevel\\fR is the state: 0 idle, 1 spinning up (at speed once |command - feedback| < threshold),
2 monitoring (under speed, sticky until the spindle is off, once command - feedback > threshold).
""";
pin in bit spindle_is_on "Spindle is commanded on";
pin in float spindle_command "Commanded speed";
pin in float spindle_feedback "Measured speed";
pin out bit spindle_at_speed;
pin out bit spindle_underspeed;
param rw u32 level "State: 0 idle, 1 spinning up, 2 monitoring";
param rw float threshold "Speed tolerance";
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
#define SM_IDLE 0
#define SM_SPINUP 1
#define SM_MONITOR 2
(void)period;
switch (level) {
case SM_IDLE:
    spindle_at_speed = 0;
    spindle_underspeed = 0;
    if (spindle_is_on)
        level = SM_SPINUP;
    break;
case SM_SPINUP:
    if (!spindle_is_on)
        level = SM_IDLE;
    if (fabs(spindle_command - spindle_feedback) < threshold) {
        level = SM_MONITOR;
        spindle_at_speed = 1;
    }
    break;
case SM_MONITOR:
    if (!spindle_is_on)
        level = SM_IDLE;
    if (spindle_command - spindle_feedback > threshold)
        spindle_underspeed = 1;
    break;
default:
    level = SM_IDLE;
    break;
}
