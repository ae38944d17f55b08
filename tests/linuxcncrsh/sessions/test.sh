#!/bin/bash
# Several linuxcncrsh sessions: one holds control at a time, --sessions limits connections,
# three wrong HELLOs close a connection, shutdown only from the session in control (it
# ends linuxcncrsh with status 0).
. "$EMC2_HOME/tests/linuxcncrsh/lib.sh"
start_machine || exit 1
start_rsh --sessions 2 || { stop_machine; exit 1; }
PYTHONPATH="$EMC2_HOME/tests/linuxcncrsh/common:$PYTHONPATH" python3 -u "$(dirname "$0")/sessions_test.py" 2>&1
rc=$?
wait "$RSH_PID"
echo "linuxcncrsh exit $?"
stop_machine
rm -f rsh.log
exit $rc
