#!/bin/bash
# positionlogger: samples the tool position in a thread while an axis jogs; points() in
# GL_C4UB_V3F records, last(), colours, clear(), stop().
. "$EMC2_HOME/tests/pylinuxcnc/lib.sh"
start_machine || exit 1
python3 -u "$(dirname "$0")/logger_test.py" 2>&1
rc=$?
stop_machine
exit $rc
