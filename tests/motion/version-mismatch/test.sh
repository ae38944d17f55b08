#!/bin/bash
# motmod refuses kinematics, planner and homing tables built for another interface version.
. "$(dirname "$0")/../../lib/testmods.sh"
log=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; tm_cleanup; rm -f "$log"' EXIT
try_with() {
    local before
    halrun -U >/dev/null 2>&1
    : >"$log"
    for m in "$@"; do halcmd loadrt "$m" >>"$log" 2>&1; done
    if halcmd loadrt motmod num_joints=3 >>"$log" 2>&1; then
        echo "loaded with: $*"
    else
        sleep 0.1
        grep -a -o 'MOTION: .*' "$log" | head -1
    fi
}
try_with motion_bad_kins tpmod homemod
try_with trivkins motion_bad_tp homemod
try_with trivkins tpmod motion_bad_home
try_with trivkins tpmod homemod
