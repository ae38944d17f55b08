#!/bin/bash
# joint_axis_mapper: pins per axis letter (repeats numbered), a message per rising fault, non-axis letters skipped.
run() { "$EMC2_HOME/objects/unit/comptest" | grep -v '^hal_init'; }
run <<'S'
load joint_axis_mapper "coord=x;y,Yq z"
show
functs joint_axis_mapper
set jam.Y2-fault 1
trace 2 jam.Y2-fault-latched
set jam.Y2-fault 0
set jam.x-fault 1
trace 1 jam.x-fault-latched jam.Y2-fault-latched
S
echo "== default coord: 18 letters, the first 16 joints"
printf 'load joint_axis_mapper\nshow\n' | run | grep -c 'fault-latched'
