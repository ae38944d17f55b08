#!/bin/bash
# Error reporting: text + source line on stderr, -n 0 continues, -n 2 stops, missing/bad/blank files, stdin MDI.
rs274 -g -n 0 test.ngc 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[0]}"
rs274 -g test.ngc 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[0]}"
rs274 -g missing.ngc 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[0]}"
rs274 -g -t missing.tbl test.ngc 2>&1 | head -n 1
printf 'G0 X3\nG1 Y1 F5\nquit\nG0 X9\n' | rs274 -g 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[1]}"
printf 'T1 P1 Z0.5\nT2 P2 K9 Z1\n' > bad.tbl
rs274 -g -t bad.tbl missing.ngc 2>&1 | head -n 1
printf '5221\t1.0\n5161\t2.0\n' > order.var
rs274 -g -v order.var test.ngc 2>&1 | tail -n 1
echo "status ${PIPESTATUS[0]}"
rm -f bad.tbl order.var
rs274 -g a b c 2>&1 | head -n 1
echo "status ${PIPESTATUS[0]}"
# a file with nothing but blank lines fails while opening: no ON_RESET at all
printf '\n  \n\t\n' > blank.ngc
rs274 -g blank.ngc 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[0]}"
rm -f blank.ngc
exit 0
