#!/bin/bash
# openemc-estimate gives the same servo-cycle count as a real linuxcnc -r run whose queue is filled
# before motion starts (it never starves): cut.ngc on the trapezoid planner (test.ini) and
# corners.ngc on the jerk-limited one (jerk.ini, made from test.ini here); spindle.ngc: the feed
# move after M3 waits for the spindle at speed, so the rapid into it stops; features.ngc on both.
. "$EMC2_HOME/tests/task/lib/run-machine.sh"
sed -e '/^\[TRAJ\]/a PLANNER_TYPE = 1\nMAX_LINEAR_JERK = 100000' \
    -e '/^\[\(AXIS\|JOINT\)_/a MAX_JERK = 100000' test.ini > jerk.ini

# compare: INI PROGRAM -> "same count" when the real run and the estimate agree
compare() {
    rm -f real-cycles.txt samples.txt test.var
    CYCLES_PROGRAM=$2 run_machine "$1" || return 1
    local real est sim
    real=$(cat real-cycles.txt)
    est=$(openemc-estimate --quiet "$1" "$2") || { echo "openemc-estimate failed"; return 1; }
    sim=$(sed -n 's/^servo cycles: .* total, \([0-9]*\) in motion$/\1/p' <<< "$est")
    echo "$1 $2: real run $real cycles, estimate $sim cycles" >&2
    [ -n "$sim" ] && [ "$real" = "$sim" ] && echo "same count" || echo "counts differ: real $real, estimate $sim"
}
compare test.ini cut.ngc
compare jerk.ini corners.ngc
compare test.ini spindle.ngc
compare test.ini features.ngc
compare jerk.ini features.ngc
