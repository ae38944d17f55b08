#!/bin/bash
# openemc-estimate on bad input: a missing INI file, a missing program, G-code the interpreter
# refuses (FILE:LINE: message), a move beyond an axis limit, bad options.  Each fails with a
# message on stderr and a non-zero status; nothing is printed on stdout.
ini=../cycles/test.ini
run() {
    local out err rc
    out=$(openemc-estimate "$@" 2> err.txt)
    rc=$?
    err=$(sed "s|$PWD/||g" err.txt | head -1)
    echo "status $rc: ${err}"
    [ -z "$out" ] || echo "unexpected output: $out"
}
run missing.ini bad.ngc
run "$ini" missing.ngc
run "$ini" bad.ngc
run "$ini" limit.ngc
run --ranges 0 "$ini" bad.ngc
run "$ini"
rm -f err.txt
