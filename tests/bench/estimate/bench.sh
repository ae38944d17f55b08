#!/bin/bash
# openemc-estimate's speed against real time: a 20000-chord spiral pocket and a 2000-corner zigzag
# (F3000, G64 P0.01) on the cycle-count test's 1 kHz machine.  Figures only.
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cp "$top/tests/estimate/cycles/test.ini" "$dir/"
: > "$dir/tool.tbl"
python3 - "$dir" <<'PY'
import math, sys
d = sys.argv[1]
with open(d + "/spiral.ngc", "w") as f:
    f.write("G21 G90 G64 P0.01\nF3000\nG0 X0 Y0\n")
    for k in range(20000):
        a = k * 0.01
        r = 2 + 60 * k / 20000
        f.write("G1 X%.4f Y%.4f\n" % (r * math.cos(a), r * math.sin(a)))
    f.write("M2\n")
with open(d + "/zigzag.ngc", "w") as f:
    f.write("G21 G90 G64 P0.01\nF3000\nG0 X-80 Y-5\n")
    for k in range(2000):
        f.write("G1 X%.3f Y%.3f\n" % (-80 + 0.08 * k, -5 if k % 2 else 5))
    f.write("M2\n")
PY
for p in spiral zigzag; do
    out=$(cd "$dir" && openemc-estimate --quiet test.ini $p.ngc 2>&1)
    speed=$(sed -n 's/^simulation: //p' <<< "$out")
    echo "estimate: $p.ngc: $speed"
done
exit 0
