#!/bin/bash
# stat against a running machine: every attribute with its Python type, the values a
# fresh machine reports, tool_table/toolinfo, a subclass, poll() copies only on demand.
. "$EMC2_HOME/tests/pylinuxcnc/lib.sh"
start_machine || exit 1
python3 -u "$(dirname "$0")/stat_test.py" 2>&1
rc=$?
stop_machine
exit $rc
