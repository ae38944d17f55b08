#!/bin/bash
# NML benchmark: linuxcnc.command() round trip (write to echoed serial) against a task
# stand-in cycling at 1 ms, wait_complete() after it, and stat.poll() calls per second.
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
. "$top/scripts/rip-environment" >/dev/null 2>&1
export OPENEMC_INSTANCE=${OPENEMC_INSTANCE:-205}
. "$top/tests/pylinuxcnc/lib.sh"
trap stop_machine EXIT
start_machine || exit 1
python3 - <<'PY'
import statistics, time, linuxcnc

s = linuxcnc.stat()
c = linuxcnc.command()
s.poll()
for _ in range(50):
    c.debug(0)
rtt = []
for _ in range(2000):
    t = time.perf_counter()
    c.debug(0)
    rtt.append((time.perf_counter() - t) * 1e3)
rtt.sort()
wc = []
for _ in range(500):
    t = time.perf_counter()
    c.debug(0)
    c.wait_complete()
    wc.append((time.perf_counter() - t) * 1e3)
wc.sort()
p99 = lambda v: v[int(len(v) * 0.99) - 1]
print("nml: command() round trip, 1 ms task cycle: median %.3f ms, p99 %.3f ms, max %.3f ms (target <= 2 ms median; LinuxCNC 20-70 ms)"
      % (statistics.median(rtt), p99(rtt), rtt[-1]))
print("nml: command() + wait_complete(): median %.3f ms, p99 %.3f ms" % (statistics.median(wc), p99(wc)))
n = 200000
t = time.perf_counter()
for _ in range(n):
    s.poll()
dt = time.perf_counter() - t
print("nml: stat.poll(): %.0f calls/s, %.2f us per call (target >= 100,000 calls/s)" % (n / dt, dt / n * 1e6))
t = time.perf_counter()
for _ in range(n):
    s.position
dt = time.perf_counter() - t
print("nml: stat.position (9-tuple) access: %.2f us" % (dt / n * 1e6))
PY
