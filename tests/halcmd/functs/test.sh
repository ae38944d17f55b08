#!/bin/bash
# addf/delf/initf positions and error texts, show thread, start/stop.
realtime start 2> /dev/null || exit 1
halcmd -k -f 2>&1 <<'HAL' | sed 's/  [0-9a-f]\{8,16\}  [0-9a-f]\{8,16\}  /  CODE  ARG  /'
setexact_for_test_suite_only
loadrt threads name1=fast period1=100000 name2=slow period2=1000000
loadrt and2 count=4
addf and2.0 fast
addf and2.1 fast 1
addf and2.2 fast -1
addf and2.3 fast 2
show thread
addf and2.0 slow
addf nosuch fast
addf and2.0 fast 0
delf and2.0 fast
delf and2.0 fast
addf and2.0 nosuch
addf and2.0 slow 5
addf and2.0 slow -5
addf and2.0 slow junk
delf and2.1
delf nosuch fast
delf and2.1 nosuch
delf and2.1 slow
show funct and2
initf and2.1 fast
initf and2.0 fast
show thread fast
save thread
start
stop
setexact_for_test_suite_only
HAL
echo "exit ${PIPESTATUS[0]}"
realtime stop
