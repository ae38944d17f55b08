#!/bin/bash
# Each *.ngc starts with ";<exact error text>"; rs274 must fail and report that text
# as the second-to-last stderr line (the last is the offending source line).
status=0
for f in *.ngc; do
    want=$(head -n 1 "$f" | sed 's/^;//')
    rs274 -g "$f" > /dev/null 2> "$f.err"
    rc=$?
    got=$(tail -n 2 "$f.err" | head -n 1)
    if [ $rc -ne 0 ] && [ "$got" = "$want" ]; then
        echo "ok $f"
    else
        echo "FAIL $f (exit $rc): $got"
        status=1
    fi
    rm -f "$f.err"
done
exit $status
