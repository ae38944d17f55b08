#!/bin/bash
# sim_matrix_kb feeding a matrix_kb 8x8 decoder in real HAL: the sampled codes and key pins, then the
# row/column/code messages (collected after halrun ends so the order is fixed).
out=$(mktemp)
trap 'rm -f "$out"' EXIT
halrun -f keypad.hal >"$out" 2>&1
echo "rc=$?"
grep -E '^[0-9]+ [01] [01] [01] $' "$out"
grep -E '^row: ' "$out"
