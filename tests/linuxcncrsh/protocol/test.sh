#!/bin/bash
# A linuxcncrsh session against nml_responder: commands before HELLO are refused, a wrong
# password, echo and verbose, control by 'set enable', state, mode, coolant, spindle,
# overrides, positions and joints, homing and jogging, MDI with wait modes, programs,
# unit reports, error replies, the error channel, help and quit.
. "$EMC2_HOME/tests/linuxcncrsh/lib.sh"
start_machine || exit 1
printf 'G0 X1\nM2\n' > prog.ngc
start_rsh || { stop_machine; exit 1; }
PYTHONPATH="$EMC2_HOME/tests/linuxcncrsh/common:$PYTHONPATH" python3 -u "$(dirname "$0")/protocol_test.py" 2>&1 |
    sed "s|$PWD/|TESTDIR/|g"   # the checkout's path is not part of the answer
rc=${PIPESTATUS[0]}
stop_rsh
stop_machine
rm -f prog.ngc rsh.log
exit $rc
