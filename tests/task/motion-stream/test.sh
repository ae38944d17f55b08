#!/bin/bash
# The command stream task sends motion (motion-logger in place of motmod): the start-up
# configuration of a 4-joint machine (inch, a rotary axis, backlash, OFFSET_AV_RATIO, jerk,
# homing flags), machine on, AUTO, a part program (lines, arc, rotary feed, dwell, tool change
# with G43, spindle, synced output) and manual jogs, homing and overrides.
. ../lib/run-machine.sh
rm -f out.motion-logger
run_machine || exit 1
cat out.motion-logger
