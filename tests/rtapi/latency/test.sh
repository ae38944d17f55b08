#!/bin/bash
# latency-test: period syntax, argument errors, and a short run whose JSON has
# one entry per thread with ordered figures (min <= p50 <= p99 <= p99.99 <= max).
export PATH=${EMC2_HOME:-$(cd ../../.. && pwd)}/bin:$PATH
for args in "-t 0" "-t abc" "5q" "0" "-1ms" "1 2 3" "--bogus"; do
    latency-test $args >/dev/null 2>err.txt
    echo "latency-test $args -> $? $(head -1 err.txt)"
done
rm -f err.txt
# check FILE: summarise the JSON report
check() {
    python3 - "$1" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
for t in r["threads"]:
    order = t["min_ns"] <= t["p50_ns"] <= t["p99_ns"] <= t["p99_99_ns"] <= t["max_ns"]
    print("%s period %d: samples %s, ordered %s" % (t["name"], t["period_ns"],
          "yes" if t["samples"] > 0 else "none", "yes" if order else "no"))
PY
}
latency-test -t 0.2 --json > both.json 2>/dev/null && check both.json
latency-test -t 0.2 --json 50us 2ms > both.json 2>/dev/null && check both.json
latency-test -t 0.2 --json 0.5ms > one.json 2>/dev/null && check one.json
latency-test -t 0.2 --json 250 > one.json 2>/dev/null && check one.json
latency-test -t 0.2 --json 250000 > one.json 2>/dev/null && check one.json
latency-test -t 0.2 100us | head -2 | sed 's/latency-test: 0.2 s, .* (/latency-test: 0.2 s, MODE (/'
rm -f both.json one.json
