#!/bin/bash
# [TRAJ]SPINDLES: $ selects the spindle of S, M3/M4/M5 ($-1 all), G96/G97 and M19; M2 stops
# every configured spindle; a $ beyond them is an error.
rs274 -i test.ini -g test.ngc 2>/dev/null | awk '{$1=""; print}' | tail -n +7
printf 'S1 $3\nM2\n' > bad.ngc
rs274 -i test.ini -g bad.ngc 2>&1 | tail -n 3
rm -f bad.ngc
exit 0
