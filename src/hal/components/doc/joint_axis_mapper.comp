component joint_axis_mapper "Messages naming the axis letter of a joint whose fault input rises";
modparam dummy coord "Axis letter of each joint, e.g. coord=xyyz (default XYZABCUVWXYZABCUVW; at most 16 joints are used)";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Blanks, tabs, line ends and the characters ; { } , \\(dq ' in coord are ignored. The first
joint with letter L gets pins jam.L-fault (bit in) and jam.L-fault-latched (bit out); the
k-th joint with the same letter (any case) gets jam.Lk-fault and jam.Lk-fault-latched.
A letter that is not an axis letter is reported and gets no pins.

The function joint_axis_mapper prints "L Axis fault detected" when jam.L-fault rises;
jam.L-fault-latched is the fault input of the previous call. The pin
joint_axis_mapper.dummy has no function.""";
