#!/bin/bash
# The 5/6-axis kinematics in the real HAL: each loads as sim configs do, shows its pins, exports the kins API.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1

# Load one module, list its pins (name dir type value) and its kinematics exports, unload it.
check_module() {
    local module=$1
    shift
    halcmd loadrt "$module" "$@" >"$out" 2>&1 || { echo "$module: load failed"; cat "$out"; return; }
    echo "$module${*:+ $*}"
    halcmd -s show pin >"$out" 2>&1
    awk 'NF >= 5 {print "  " $5, $3, $2, $4}' "$out" | sort
    nm -D --defined-only "$EMC2_HOME/rtlib/$module.so" | awk '$3 ~ /^kin/ {printf " %s", $3} END {print ""}'
    halcmd unload "$module" >"$out" 2>&1 || echo "$module: unload failed"
}

check_module xyzac-trt-kins coordinates=xyzac
check_module xyzbc-trt-kins
check_module 5axiskins
check_module maxkins
check_module xyzab_tdr_kins
check_module xyzacb_trsrn
check_module xyzbca_trsrn
halcmd loadrt xyzac-trt-kins coordinates=xyzbc >"$out" 2>&1 && echo "missing A was accepted"
grep -a -o "xyzac-trt-kins: ERROR: coordinates need a joint for axis A" "$out" | head -1
halcmd loadrt 5axiskins coordinates=xyzbcq >"$out" 2>&1 && echo "bad letter was accepted"
grep -a -o "Invalid character 'q' in coordinates 'xyzbcq'" "$out" | head -1
