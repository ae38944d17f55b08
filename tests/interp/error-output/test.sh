#!/bin/bash
# Error reporting: text + source line on stderr, -n 0 continues, -n 2 stops, missing files, stdin MDI.
rs274 -g -n 0 test.ngc 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[0]}"
rs274 -g test.ngc 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[0]}"
rs274 -g missing.ngc 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[0]}"
rs274 -g -t missing.tbl test.ngc 2>&1 | head -n 1
printf 'G0 X3\nG1 Y1 F5\nquit\nG0 X9\n' | rs274 -g 2>&1 | awk '{$1=""; print}'
echo "status ${PIPESTATUS[1]}"
rs274 -g a b c 2>&1 | head -n 1
echo "status ${PIPESTATUS[0]}"
exit 0
