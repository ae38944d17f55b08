#!/bin/bash
# The parallel kinematics modules (deltas, tripod, rose, pentapod) in the real HAL: pins and exports.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt lineardeltakins L=1 >"$out" 2>&1 && echo "unknown argument was accepted"
grep -o "Unknown parameter \`L=1'" "$out" | head -1
for m in lineardeltakins rotarydeltakins tripodkins rosekins pentakins; do
    halcmd loadrt $m >"$out" 2>&1 && echo "loaded $m"
    nm -D --defined-only "$EMC2_HOME/rtlib/$m.so" | awk '{print $3}' | grep -E '^kin' | tr '\n' ' '
    echo
done
halcmd setp lineardeltakins.L 300 >"$out" 2>&1 && echo "setp done"
halcmd -s show pin >"$out" 2>&1
awk '$5 ~ /^(lineardelta|rotarydelta|tripod|rose)kins/ {print $2, $3, $4, $5}' "$out"
echo "pentakins pins: $(grep -c 'pentakins\.' "$out")"
grep -E 'pentakins\.(tool-offset|limit-iterations|max-error)$' "$out" | awk '{print $2, $3, $4, $5}'
halcmd -s show param >"$out" 2>&1
grep -E 'pentakins\.(base\.4\.z|effector\.3\.z)$' "$out" | awk '{print $2, $3, $4, $5}'
for m in lineardeltakins rotarydeltakins tripodkins rosekins pentakins; do
    halcmd unload $m >"$out" 2>&1 && echo "unloaded $m"
done
