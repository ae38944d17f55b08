component spindle "Spindle speed control with gears, speed limits, acceleration and deceleration";
modparam dummy count "Number of instances (default 1)";
modparam dummy names "Names of the instances (instead of count)";
modparam dummy numgears "Gears of each instance, 1..16 (default 1)";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Per gear g: scale.g, min.g, max.g, accel.g, decel.g, speed-tolerance.g,
zero-tolerance.g, offset.g and select.g (TRUE at load when there is one gear). The gear
is select-gear when not 0, else the highest selected one.

Each call the speed (spindle-rpm: actual-speed x 60, or the component's own value with
simulate-encoder) moves toward commanded-speed (0 unless enable) within accel and decel
(per call, or per second in simulation), never crossing zero in one step, clamped to the
gear's min and max (limited). at-speed is within speed-tolerance; zero-speed within
zero-tolerance; forward/reverse give the direction; output = (|speed| + offset) x scale.
spindle-rpm-abs is |speed|, low-pass filtered by spindle-lpf while at speed.""";
