#!/bin/bash
# halui program buttons in AUTO mode: run (refused without an open program), pause, resume,
# step, stop, and the program status pins.
. "$EMC2_HOME/tests/halui/lib.sh"
# a program that runs a few seconds on task and on the responder (a line per 2 ms)
{ for i in $(seq 2000); do echo "G4 P0.002"; done; echo M2; } > halui-program.ngc
start_halui || exit 1
PYTHONPATH="$EMC2_HOME/tests/halui/common:$PYTHONPATH" python3 -u "$(dirname "$0")/program_test.py" 2>&1
rc=$?
stop_halui
rm -f halui-program.ngc
exit $rc
