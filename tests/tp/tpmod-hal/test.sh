#!/bin/bash
# tpmod in the real HAL: a pinless component that takes (and ignores) tp_parms and exports tp_ops.
out=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$out"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt tpmod tp_parms=anything >"$out" 2>&1 && echo loaded
halcmd -s show comp >"$out" 2>&1
awk '$3 == "tpmod" {print $2, $3}' "$out"
halcmd -s show pin tpmod >"$out" 2>&1
echo "pins: $(grep -c tpmod "$out")"
nm -D --defined-only "$EMC2_HOME/rtlib/tpmod.so" | awk '{print $3}' | grep -E '^tp_' | sort
halcmd unload tpmod >"$out" 2>&1 && echo unloaded
