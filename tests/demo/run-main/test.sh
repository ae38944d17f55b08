#!/bin/bash
# The make-run demo must print 60 samples in which limit3 keeps its 40 u/s slew
# limit, lowpass stays between the square wave's extremes and the square wave flips;
# then the G-code part must show the tool-radius-offset outline and the call counts.
set -e
"$EMC2_HOME/scripts/run-main" > demo.out
awk 'NF == 6 && $1 ~ /^[0-9]+$/ {
        rows++
        if ($6 > 40.0001 || $6 < -40.0001) bad = bad "slew " $0 "\n"
        if ($4 > 10 || $4 < -10) bad = bad "lowpass " $0 "\n"
        if ($2 != prev && rows > 1) flips++
        prev = $2
     }
     END {
        print "rows", rows
        print "square flips", (flips >= 2 ? "yes" : "no")
        printf "%s", bad
     }' demo.out
grep -E '^ +[0-9]+ calls:' demo.out
grep -c '^    STRAIGHT_FEED(32.0003, 27.0003, -2.0000' demo.out
rm -f demo.out
