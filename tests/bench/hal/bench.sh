#!/bin/bash
# HAL benchmark: ns per call of 1,000 trivial functs in one thread (timing on), 10,000 functs in memory, bytes per pin/signal.
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
. "$top/scripts/rip-environment" >/dev/null 2>&1
export OPENEMC_INSTANCE=${OPENEMC_INSTANCE:-201}
. "$top/tests/lib/testmods.sh"
trap tm_cleanup EXIT
realtime start 2>/dev/null || exit 1
halcmd loadrt hal_bench count=1000 period=1000000 || exit 1
halcmd start
for i in $(seq 1 2000); do
    [ "$(halcmd getp hal-bench.cycles)" -ge 500 ] && break
    sleep 0.01
done
halcmd stop
sum=$(halcmd getp hal-bench.sum-ns)
n=$(halcmd getp hal-bench.cycles)
min=$(halcmd getp hal-bench.min-ns)
awk -v s="$sum" -v n="$n" -v m="$min" 'BEGIN { printf "hal: 1000 functs per cycle, %d cycles: %.2f ns per funct call (incl. timing; mean), %.2f ns (best cycle)\n", n, s / n / 1001, m / 1001 }'
halcmd unloadrt hal_bench
halcmd loadrt hal_bench count=10000 period=0 || exit 1
halcmd status mem | sed -n 's/^ *used\/total shared memory: */hal: arena after 10,000 functs (+ .time pins, .tmax params): /p'
realtime stop
"$top/objects/unit/hal_bench_mem" | sed 's/^/hal: /'
