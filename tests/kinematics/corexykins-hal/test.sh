#!/bin/bash
# The cartesian kinematics modules (corexykins, rotatekins, scorbot-kins, matrixkins) in the real HAL.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt corexykins bogus=1 >"$out" 2>&1 && echo "unknown argument was accepted"
grep -o "Unknown parameter \`bogus=1'" "$out" | head -1
for m in corexykins rotatekins scorbot-kins matrixkins; do
    halcmd loadrt $m >"$out" 2>&1 && echo "loaded $m"
    nm -D --defined-only "$EMC2_HOME/rtlib/$m.so" | awk '{print $3}' | grep -E '^kin' | tr '\n' ' '
    echo
done
halcmd -s show comp >"$out" 2>&1
awk '$3 ~ /kins/ {print $2, $3, $4}' "$out" | sort -k2
halcmd -s show pin >"$out" 2>&1
echo "pins of the pinless modules: $(grep -cE 'corexykins|rotatekins|scorbot-kins' "$out")"
echo "matrixkins at load (its C_xx..C_zz params come with motion's first type query):"
halcmd -s show pin >"$out" 2>&1
awk '$5 ~ /^matrixkins/ {print $2, $3, $4, $5}' "$out"
halcmd -s show param >"$out" 2>&1
echo "matrixkins params: $(grep -c 'matrixkins' "$out")"
for m in corexykins rotatekins scorbot-kins matrixkins; do
    halcmd unload $m >"$out" 2>&1 && echo "unloaded $m"
done
