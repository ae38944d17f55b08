#!/bin/bash
# A task runs at its requested period: in non-realtime mode each cycle's
# reference is exactly first + n*period, no wake-up is early, every rtapi_wait is
# counted, and a cycle that overruns by 5.5 periods is caught up (>= 5 overruns
# counted, no period skipped). The module prints its verdict after N cycles.
. ../lib.sh
# wait_for TEXT: wait (bounded) until the master printed TEXT into result
wait_for() {
    local i
    for ((i = 0; i < 600; i++)); do
        grep -q "$1" result && return 0
        sleep 0.1
    done
    echo "gave up waiting for '$1'"
}
realtime start
rtapi_app load rtapi_test_task period=1000000 cycles=100
wait_for "^task: 100 calls"
rtapi_app unload rtapi_test_task
rtapi_app load rtapi_test_task period=100000 cycles=500 stall=5
wait_for "^task: 500 calls"
rtapi_app unload rtapi_test_task
realtime stop
