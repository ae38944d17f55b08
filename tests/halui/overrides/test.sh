#!/bin/bash
# halui override knobs: feed, rapid, spindle and max velocity through counts (relative and
# direct), increase/decrease/reset, count-enable, and the INI limits they are clamped to.
. "$EMC2_HOME/tests/halui/lib.sh"
start_halui || exit 1
PYTHONPATH="$EMC2_HOME/tests/halui/common:$PYTHONPATH" python3 -u "$(dirname "$0")/overrides_test.py" 2>&1
rc=$?
stop_halui
exit $rc
