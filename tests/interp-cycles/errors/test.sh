#!/bin/bash
# Canned-cycle and G76 error paths: each program must stop with exit 1 and the exact error text.
for f in *.ngc; do
    rs274 -t test.tbl -g "$f" > /dev/null 2> stderr.txt
    rc=$?
    # the error text is the second-to-last stderr line, the offending line the last
    echo "$f rc=$rc: $(tail -n 2 stderr.txt | tr '\n' '|')"
done
rm -f stderr.txt
