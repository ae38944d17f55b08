#!/bin/bash
# trivkins in the real HAL: a bad coordinates letter refuses the load; a good one exports the kins API.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt trivkins coordinates=xq >"$out" 2>&1 && echo "bad coordinates were accepted"
grep -o "Invalid character 'q' in coordinates 'xq'" "$out" | head -1
halcmd loadrt trivkins coordinates=xyyz kinstype=both >"$out" 2>&1 && echo loaded
halcmd -s show comp >"$out" 2>&1
awk '$3 == "trivkins" {print $2, $3, $4}' "$out"
nm -D --defined-only "$EMC2_HOME/rtlib/trivkins.so" | awk '{print $3}' | grep -E '^kin' | sort
halcmd unload trivkins >"$out" 2>&1 && echo unloaded
