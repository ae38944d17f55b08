#!/bin/bash
# genhexkins in the real HAL: load as the hexapod sim does, pins and defaults, exports, bad argument.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt genhexkins coordinates=xyzq >"$out" 2>&1 && echo "bad coordinates were accepted"
grep -o "Invalid character 'q' in coordinates 'xyzq'" "$out" | head -1
halcmd loadrt genhexkins coordinates=xyzabc >"$out" 2>&1 && echo loaded
halcmd -s show pin >"$out" 2>&1
awk '$5 ~ /^(genhexkins\.(base\.0|platform\.5|base-n\.3|platform-n\.1)\.|genhexkins\.[a-z-]+$|skgui|kinstype|userk)/ {print $2, $3, $4, $5}' "$out"
grep -c 'genhexkins\.' "$out"
halcmd setp genhexkins.limit-iterations 50 >"$out" 2>&1 && halcmd -s getp genhexkins.limit-iterations
nm -D --defined-only "$EMC2_HOME/rtlib/genhexkins.so" | awk '{print $3}' | grep -E '^kin' | sort
halcmd unload genhexkins >"$out" 2>&1 && echo unloaded
