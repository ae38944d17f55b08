#!/bin/bash
# Work offsets, G92 family, rotation, G28/G30 and G53; stored values land in the .var file (inches).
printf '5161\t1.0\n5181\t0.5\n5182\t0.25\n' > offsets.var
rs274 -g -v offsets.var test.ngc | awk '{$1=""; print}'
status=${PIPESTATUS[0]}
grep -E '^(5161|5181|5182|5220|5221|5222|5250|5261|5281)' offsets.var
exit "$status"
