#!/bin/bash
# rs274 throughput: canon output to /dev/null for a 1,000,000-line G1 XYZ program and an
# expression-heavy program; prints lines per second (target >= 1.5M lines/s on the G1 program).
set -e
TOP=$(cd "$(dirname "$0")/../../.." && pwd)
RS274=${RS274:-$TOP/bin/rs274}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
LINES=${BENCH_LINES:-1000000}

awk -v n="$LINES" 'BEGIN {
    print "G21 G90 G17 F1000"
    for (i = 0; i < n; i++)
        printf "G1 X%.3f Y%.3f Z%.3f\n", (i % 1000) * 0.013, (i % 777) * 0.021, -(i % 13) * 0.1
    print "M2"
}' > "$WORK/g1.ngc"

awk -v n="$LINES" 'BEGIN {
    print "#1 = 0"
    print "#<acc> = 0"
    for (i = 0; i < n; i++)
        printf "#<acc> = [#<acc> + SIN[%d] * COS[#1] + SQRT[ABS[#<acc>] + %d] MOD 7 - [2 ** 3] / 4]\n", i % 360, i % 91
    print "(debug,acc=#<acc>)"
    print "M2"
}' > "$WORK/expr.ngc"

# seconds of user+system CPU for one run of rs274 on $1
cpu_seconds() {
    /usr/bin/time -f "%U %S" -o "$WORK/time" "$RS274" -g "$1" > /dev/null 2> /dev/null
    awk '{print $1 + $2}' "$WORK/time"
}

for prog in g1 expr; do
    best=
    for run in 1 2 3; do
        s=$(cpu_seconds "$WORK/$prog.ngc")
        if [ -z "$best" ] || awk -v a="$s" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$s; fi
    done
    awk -v n="$LINES" -v s="$best" -v p="$prog" \
        'BEGIN { if (s <= 0) s = 0.01; printf "rs274 %-5s %d lines: %.2f s CPU, %.0f lines/s\n", p, n, s, n / s }'
done
