#!/bin/bash
# halui.mdi-command-NN ([HALUI]MDI_COMMAND): switch to MDI, run, return to the operator's
# mode; halui.halui-mdi-is-running; refused while the machine is off.
. "$EMC2_HOME/tests/halui/lib.sh"
start_halui || exit 1
PYTHONPATH="$EMC2_HOME/tests/halui/common:$PYTHONPATH" python3 -u "$(dirname "$0")/mdi_test.py" 2>&1
rc=$?
stop_halui
exit $rc
