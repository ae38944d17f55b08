#!/bin/bash
# userkins in the real HAL: the halcompile-built template loads, shows its pins and exports kins_ops.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt userkins >"$out" 2>&1 && echo loaded
halcmd -s show pin >"$out" 2>&1
awk 'NF >= 5 {print $2, $3, $4, $5}' "$out"
halcmd -s show funct >"$out" 2>&1
grep -c userkins "$out"
nm -D --defined-only "$EMC2_HOME/rtlib/userkins.so" | awk '{print $3}' | grep -E '^kin' | sort
halcmd unload userkins >"$out" 2>&1 && echo unloaded
