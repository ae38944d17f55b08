#!/bin/bash
# Runs signals.hal with halrun, then checks that the session left no realtime master
# and no HAL shared memory behind on this test's instance.
halrun signals.hal || exit 1
if rtapi_app ping; then echo "a master still answers"; else echo "no master answers"; fi
left=0
for p in $(pgrep -x rtapi_app); do
    if tr '\0' '\n' < "/proc/$p/environ" 2>/dev/null | grep -qx "OPENEMC_INSTANCE=$OPENEMC_INSTANCE" &&
        [ "$(ps -o stat= -p "$p" | cut -c1)" != Z ]; then
        left=$((left + 1))
    fi
done
echo "rtapi_app processes left: $left"
