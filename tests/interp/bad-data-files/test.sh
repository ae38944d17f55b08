#!/bin/bash
# A .var file line with a non-numeric or non-finite value or an out-of-range number stops the
# start with file:line and leaves the file as it was; a tool table line that cannot be parsed
# (unknown letter, bad or non-finite number) is skipped with a warning.
status=0
for body in '5220\t1\n5221\tabc\n' '5220\t1\n9999\t2\n' '5220\t1\n5221\tnan\n' '5221\tinf\n' \
            '5221\t1\n5220\t1\n'; do
    printf "$body" > bad.var
    cp bad.var orig.var
    rs274 -g -v bad.var m2.ngc > out.txt 2> err.txt && status=1
    grep -v '^executing$' err.txt
    cmp -s bad.var orig.var || { echo "bad.var changed"; status=1; }
    [ -e bad.var.bak ] && { echo "bad.var rewritten"; status=1; }
    [ -s out.txt ] && { echo "canon output after a refused .var file"; status=1; }
done
printf 'T1 P1 Z0.5 D0.25 ;ok\nT2 P2 Z1 K3\nT3 P3 Znan\nT4 P4 X1.5 Z0.1\nT5 P5 Z1e999\n' > tools.tbl
printf 'T1 M6 G43\nT4 M6 G43\nT2\nM2\n' > use.ngc
rs274 -g -t tools.tbl use.ngc 2>&1 | grep -E 'skipped|OFFSET|not found|^T2'
rm -f bad.var orig.var bad.var.bak out.txt err.txt tools.tbl use.ngc
exit $status
