#!/bin/bash
# millturn in the real HAL: the load makes fpin and the fdemo funct (the kinematics pins come with motion's
# first type query), exports, an argument millturn does not have.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt millturn coordinates=zxyc >"$out" 2>&1 && echo "an unknown argument was accepted"
grep -o "Unknown parameter \`coordinates=zxyc'" "$out" | head -1
halcmd loadrt millturn >"$out" 2>&1 && echo loaded
halcmd -s show pin >"$out" 2>&1
awk 'NF >= 5 && $5 !~ /\.time$/ {print $2, $3, $4, $5}' "$out"
halcmd -s show funct >"$out" 2>&1
awk 'NF {print $NF}' "$out"
halcmd -s show comp >"$out" 2>&1
awk '$3 == "millturn" {print $2, $3, $4}' "$out"
nm -D --defined-only "$EMC2_HOME/rtlib/millturn.so" | awk '{print $3}' | grep -E '^kin' | sort
halcmd unload millturn >"$out" 2>&1 && echo unloaded
