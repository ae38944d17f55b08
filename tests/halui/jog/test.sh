#!/bin/bash
# halui jogging: joint and axis plus/minus, increments, analog inputs with a deadband, the
# selected joint/axis, jogs refused in the wrong motion mode, position pins.
. "$EMC2_HOME/tests/halui/lib.sh"
start_halui || exit 1
PYTHONPATH="$EMC2_HOME/tests/halui/common:$PYTHONPATH" python3 -u "$(dirname "$0")/jog_test.py" 2>&1
rc=$?
stop_halui
exit $rc
