#!/bin/bash
# Start-up code, ON_ABORT_COMMAND, M100-M199 programs, M66 (timeout and input), probing
# (#5061-#5070, motion's probe errors) and a limit switch fault reaching the error channel.
. ../lib/run-machine.sh
rm -f m101.out
run_machine || exit 1
cat m101.out
rm -f m101.out
