#!/bin/bash
# halui spindle buttons (start/forward/reverse/stop/increase/decrease/brake) on two spindles
# and the spindle status pins.
. "$EMC2_HOME/tests/halui/lib.sh"
start_halui || exit 1
PYTHONPATH="$EMC2_HOME/tests/halui/common:$PYTHONPATH" python3 -u "$(dirname "$0")/spindle_test.py" 2>&1
rc=$?
stop_halui
exit $rc
