#!/bin/bash
# millturn in the real HAL: load with the mill-turn sim's joints, switch pins, exports, bad argument.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt millturn coordinates=zxyc >"$out" 2>&1 && echo "a map not starting with XYZ was accepted"
grep -o "coordinates must start with XYZ (joints 0..2)" "$out" | head -1
halcmd loadrt millturn coordinates=xyzac >"$out" 2>&1 && echo loaded
halcmd -s show pin >"$out" 2>&1
awk 'NF >= 5 {print $2, $3, $4, $5}' "$out"
halcmd -s show comp >"$out" 2>&1
awk '$3 == "millturn" {print $2, $3, $4}' "$out"
nm -D --defined-only "$EMC2_HOME/rtlib/millturn.so" | awk '{print $3}' | grep -E '^kin' | sort
halcmd unload millturn >"$out" 2>&1 && echo unloaded
