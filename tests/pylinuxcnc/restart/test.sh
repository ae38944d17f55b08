#!/bin/bash
# Channel objects made before the machine starts attach once it runs, fail cleanly while it
# is down, and reattach after a restart (new buffers, new tool data).
. "$EMC2_HOME/tests/pylinuxcnc/lib.sh"
rm -f step.* 
python3 -u "$(dirname "$0")/restart_test.py" &
py=$!
wait_for() { for i in $(seq 400); do [ -f "$1" ] && return 0; sleep 0.025; done; return 1; }
wait_for step.made || exit 1
start_machine || exit 1
touch step.up1
wait_for step.polled || exit 1
stop_machine
touch step.down
wait_for step.failed || exit 1
start_machine || exit 1
touch step.up2
wait $py
rc=$?
stop_machine
rm -f step.*
exit $rc
