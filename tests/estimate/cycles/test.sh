#!/bin/bash
# openemc-estimate gives the same servo-cycle count as a real linuxcnc -r run of cut.ngc whose
# queue is filled before motion starts (it never starves), and runs faster than real time.
. "$EMC2_HOME/tests/task/lib/run-machine.sh"
rm -f real-cycles.txt samples.txt test.var
run_machine || exit 1
real=$(cat real-cycles.txt)
est=$(openemc-estimate --quiet test.ini cut.ngc) || { echo "openemc-estimate failed"; exit 1; }
sim=$(sed -n 's/^servo cycles: .* total, \([0-9]*\) in motion$/\1/p' <<< "$est")
echo "real run: $real cycles, estimate: $sim cycles" >&2
[ -n "$sim" ] && [ "$real" = "$sim" ] && echo "same count" || echo "counts differ: real $real, estimate $sim"
