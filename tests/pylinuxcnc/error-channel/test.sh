#!/bin/bash
# error_channel: one queue for the whole system: every message reaches exactly one reader,
# in order, whichever process polls first; kinds and texts of every message type.
. "$EMC2_HOME/tests/pylinuxcnc/lib.sh"
start_machine || exit 1
python3 -u "$(dirname "$0")/errors_test.py" 2>&1
rc=$?
stop_machine
exit $rc
