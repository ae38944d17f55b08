#!/bin/bash
# command against a running machine: serials, echo, wait_complete, rejections with their
# error texts, state and mode changes, overrides, I/O, spindle and coolant.
. "$EMC2_HOME/tests/pylinuxcnc/lib.sh"
start_machine || exit 1
python3 -u "$(dirname "$0")/command_test.py" 2>&1
rc=$?
stop_machine
exit $rc
