#!/bin/bash
# motmod module parameters: every out-of-range value and bad combination refuses the load with its
# MOTION: text; a segment owned by a running motion-logger is refused too.
log=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$log"' EXIT
halrun -U >/dev/null 2>&1
# rtapi_app inherits this first halcmd's stderr: its messages append to $log.
halcmd loadrt and2 >>"$log" 2>&1
try() {
    local before
    before=$(wc -l <"$log")
    if halcmd loadrt motmod "$@" >>"$log" 2>&1; then
        echo "loaded: $*"
        halcmd unload motmod >>"$log" 2>&1
    else
        sleep 0.1
        tail -n +"$((before + 1))" "$log" | grep -a -o 'MOTION: .*' | head -1
    fi
}
try num_joints=3
halcmd loadrt trivkins >>"$log" 2>&1
try num_joints=3
halcmd -f ../common/planner.hal >>"$log" 2>&1
try num_joints=0
try num_joints=17
try num_joints=3 num_spindles=9
try num_joints=3 num_dio=0
try num_joints=3 num_dio=65
try num_joints=3 num_aio=0
try num_joints=3 num_misc_error=65
try num_joints=3 num_extrajoints=4
try num_joints=3 num_extrajoints=1
try num_joints=3 num_dio=2 names_din=a,b
try num_joints=3 num_aio=2 names_aout=x
try num_joints=3 num_misc_error=1 names_misc_errors=e
try num_joints=3 names_din=a,,b
try num_joints=3 servo_period_nsec=0
try num_joints=3 unlock_joints_mask=0x10000
try num_joints=3 key=0
try num_joints=3 num_spindles=0
try num_joints=16 num_spindles=8 num_dio=64 num_aio=64 num_misc_error=64
halcmd unload trivkins >>"$log" 2>&1
halcmd loadrt trivkins kinstype=both >>"$log" 2>&1
try num_joints=3 num_extrajoints=1
# a running motion-logger owns the motion segment: motmod refuses to take it over
halcmd loadusr -W motion-logger /dev/null >>"$log" 2>&1
try num_joints=3 | sed 's/(pid [0-9]*)/(pid N)/'
