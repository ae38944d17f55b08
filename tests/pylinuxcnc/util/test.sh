#!/bin/bash
# linuxcnc_util against a running machine: startup wait, homing wait, axis jog with the
# stop check, interpreter and tool waits, and their timeouts.
. "$EMC2_HOME/tests/pylinuxcnc/lib.sh"
start_machine || exit 1
python3 -u "$(dirname "$0")/util_test.py" 2>&1 | sed "s/after [0-9.]* seconds/after N seconds/"
rc=${PIPESTATUS[0]}
stop_machine
exit $rc
