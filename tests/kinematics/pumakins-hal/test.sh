#!/bin/bash
# The serial-arm kinematics in the real HAL: load as sim configs do, pins, setp, exports, bad args.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
for mod in pumakins scarakins three21kins genserkins; do
    echo "== $mod"
    halcmd loadrt $mod >"$out" 2>&1 || { echo "load failed"; cat "$out"; }
    halcmd -s show pin >"$out" 2>&1
    awk 'NF {print $2, $3, $4, $5}' "$out"
    nm -D --defined-only "$EMC2_HOME/rtlib/$mod.so" | awk '{print $3}' | grep -E '^kin' | sort | tr '\n' ' '
    echo
    halcmd unload $mod >"$out" 2>&1 && echo unloaded
done
echo "== setp and coordinates="
halcmd loadrt genserkins coordinates=xyzabc >"$out" 2>&1 && echo loaded
halcmd setp genserkins.A-2 250 >"$out" 2>&1
halcmd setp genserkins.max-iterations 50 >"$out" 2>&1
halcmd -s show pin genserkins.A-2 genserkins.max-iterations >"$out" 2>&1
awk 'NF {print $2, $3, $4, $5}' "$out"
halcmd setp genserkins.last-iterations 3 >"$out" 2>&1 && echo "setting an OUT pin was accepted"
halcmd unload genserkins >"$out" 2>&1 && echo unloaded
echo "== bad coordinates"
halcmd loadrt scarakins coordinates=xyzw7 >"$out" 2>&1 && echo "bad coordinates were accepted"
grep -a -o "scarakins: ERROR: Invalid character '7' in coordinates 'xyzw7'" "$out" | head -1
halcmd -s show comp >"$out" 2>&1
grep -c scarakins "$out"
halcmd -s show pin >"$out" 2>&1
grep -c kinstype "$out"
exit 0
