#!/bin/bash
# nmlcmd: status as text and JSON, state/mode/MDI commands with -w, a rejected command,
# scripts with file:line errors, the error channel, and no machine at all.
. "$EMC2_HOME/tests/pylinuxcnc/lib.sh"
run() { echo "\$ nmlcmd $*"; nmlcmd "$@" 2>&1; echo "exit $?"; }
start_machine || exit 1
run status task_state task_mode interp_state state
echo "\$ nmlcmd status --json estop homed"
nmlcmd status --json estop homed | python3 -c 'import json, sys; print(sorted(json.load(sys.stdin).items()))'
run -w home 0
run errors
run -w state estop_reset
run -w state on
run -w mode manual
run -w home all
for i in $(seq 200); do nmlcmd status homed | grep -q '(1, 1, 1,' && break; sleep 0.05; done
run -w mode mdi
run -w mdi G0 X0.5
run status position
run msg text hello from nmlcmd
run errors
printf '# a script\nmode manual\nfeedrate 1.5\nmist sideways\nflood on\n' > script.cmd
run -w -f script.cmd
run -w -k -f script.cmd
run status feedrate flood
run status no_such_field
run frobnicate
run -w mode
rm -f script.cmd
stop_machine
run status | sed 's/instance [0-9]*/instance N/'
