#!/bin/bash
# genserkins urdf=: chain reader unit test, the module with a URDF chain (fake HAL), then real HAL.
"$EMC2_HOME/objects/unit/genser_urdf_unit" 2>/dev/null || echo "urdf unit test failed"
"$EMC2_HOME/objects/unit/comptest" < script 2>/dev/null
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
here=$(pwd)
halrun -U >/dev/null 2>&1
echo "== real HAL: loadrt genserkins urdf=puma560.urdf urdf_scale=1000"
halcmd loadrt genserkins urdf="$here/puma560.urdf" urdf_scale=1000 >"$out" 2>&1 && echo loaded
halcmd -s show pin genserkins.max-iterations kinstype.is-0 >"$out" 2>&1
awk 'NF {print $2, $3, $4, $5}' "$out"
halcmd unload genserkins >"$out" 2>&1 && echo unloaded
echo "== real HAL: a branching URDF and a bad scale are refused"
halcmd loadrt genserkins urdf="$here/branch.urdf" >"$out" 2>&1 && echo "branch.urdf was accepted"
grep -a -o "branch.urdf': link 'link2' has 2 child joints (a single chain is needed)" "$out"
halcmd loadrt genserkins urdf="$here/puma560.urdf" urdf_scale=abc >"$out" 2>&1 && echo "bad scale accepted"
grep -a -o "genserkins: ERROR: urdf_scale 'abc' is not a positive number" "$out"
halcmd -s show pin >"$out" 2>&1
echo "pins left: $(grep -c genserkins "$out")"
exit 0
