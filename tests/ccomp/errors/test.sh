#!/bin/bash
# Cutter comp geometry errors: short entry, arc after G40, tool too big for an inside arc, concave gouges.
for f in *.ngc; do
    rs274 -t test.tbl -g "$f" > /dev/null 2> stderr.txt
    rc=$?
    # the error text is the second-to-last stderr line, the offending line the last
    echo "$f rc=$rc: $(tail -n 2 stderr.txt | tr '\n' '|')"
done
rm -f stderr.txt
