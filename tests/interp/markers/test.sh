#!/bin/bash
# N markers in canon output, '%' program delimiters, block delete on (-b) and off.
rs274 -g test.ngc | awk '{$1=""; print}'
s1=${PIPESTATUS[0]}
rs274 -b -g test.ngc | awk '{$1=""; print}' | grep TRAVERSE
s2=${PIPESTATUS[0]}
printf '%%\nG0 X1\nM2\n' > nopercent.ngc
rs274 -g nopercent.ngc | awk '{$1=""; print}' | tail -5
s3=${PIPESTATUS[0]}
rm -f nopercent.ngc
exit $((s1 + s2 + s3))
