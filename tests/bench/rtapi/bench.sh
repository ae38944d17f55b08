#!/bin/sh
# bench.sh: RTAPI timing figures: latency-test for 10 s with a 25 us base and a
# 1 ms servo thread (p99.99 and max wake-up jitter), then the wake-up-to-function
# overhead of a single empty 1 ms thread. Mode (realtime or not) as librtapi picks it.
set -eu
seconds=${RTAPI_BENCH_SECONDS:-10}
latency-test -t "$seconds" --json 25us 1ms > latency.json
latency-test -t "$seconds" --json 1ms > empty.json
python3 - latency.json empty.json <<'PY'
import json, sys
both = json.load(open(sys.argv[1]))
empty = json.load(open(sys.argv[2]))
print("mode: %s" % both["realtime_type"])
for t in both["threads"]:
    print("%-5s %8d ns period: p99.99 jitter %9.1f us, max jitter %9.1f us, overruns %d"
          % (t["name"], t["period_ns"], t["p99_99_ns"] / 1e3, t["max_ns"] / 1e3, t["overruns"]))
t = empty["threads"][0]
print("empty 1 ms thread wake-up-to-function: p50 %.1f us, p99 %.1f us, max %.1f us"
      % (t["p50_ns"] / 1e3, t["p99_ns"] / 1e3, t["max_ns"] / 1e3))
PY
rm -f latency.json empty.json
