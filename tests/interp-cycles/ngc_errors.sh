# ngc_errors.sh: shared helper of the ngc error tests (tests/interp-cycles/errors, tests/ccomp/errors).

# report_ngc_errors TOOLTABLE: run rs274 on every *.ngc here; print the exit status and the last two
# stderr lines (the error text, then the offending line) of each program.
report_ngc_errors() {
    local f rc
    for f in *.ngc; do
        rs274 -t "$1" -g "$f" > /dev/null 2> stderr.txt
        rc=$?
        echo "$f rc=$rc: $(tail -n 2 stderr.txt | tr '\n' '|')"
    done
    rm -f stderr.txt
}
