#!/bin/bash
# openemc-estimate on bad input: a missing INI file, a missing program, G-code the interpreter
# refuses (FILE:LINE: message), a move beyond an axis limit, bad options.  Each fails with a
# message on stderr and a non-zero status; nothing is printed on stdout.
# the cycles test's machine, in a directory of our own with its own tool table (that test
# writes its tool.tbl when it runs, perhaps at the same time as this one)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp ../cycles/test.ini "$work/"
cp ../cycles/tool.tbl.in "$work/tool.tbl"
ini=$work/test.ini
run() {
    local out err rc
    out=$(openemc-estimate "$@" 2> err.txt)
    rc=$?
    err=$(sed "s|$PWD/||g; s|$work/||g" err.txt | head -1)
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
