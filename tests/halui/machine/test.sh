#!/bin/bash
# halui buttons for E-stop, machine power, modes, coolant, program flags, abort and homing,
# and the status pins they drive, against nml_responder.
. "$EMC2_HOME/tests/halui/lib.sh"
start_halui || exit 1
PYTHONPATH="$EMC2_HOME/tests/halui/common:$PYTHONPATH" python3 -u "$(dirname "$0")/machine_test.py" 2>&1
rc=$?
stop_halui
exit $rc
