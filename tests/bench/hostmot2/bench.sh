#!/bin/bash
# hostmot2 benchmark: hm2_eth read-request + read + write per 1 ms servo cycle against mesa-sim on
# loopback (p50, p99, max over 5000 cycles, from the functs' .time pins sampled every cycle).
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
. "$top/scripts/rip-environment" > /dev/null 2>&1
export OPENEMC_INSTANCE=${OPENEMC_INSTANCE:-$((200 + $$ % 50))}
tmp=$(mktemp -d)
ip=127.$((20 + OPENEMC_INSTANCE / 250)).$((OPENEMC_INSTANCE % 250)).1
cycles=5000
mkfifo "$tmp/sim.in"
mesa-sim --ip "$ip" --board 7i92 --loop stepgen0:encoder0 < "$tmp/sim.in" > "$tmp/sim.out" 2>&1 &
sim=$!
exec 3> "$tmp/sim.in"
trap 'halcmd stop > /dev/null 2>&1; halcmd unload all > /dev/null 2>&1; realtime stop > /dev/null 2>&1;
      echo quit >&3; exec 3>&-; wait $sim 2> /dev/null; rm -rf "$tmp"' EXIT
for i in $(seq 100); do grep -q '^ready' "$tmp/sim.out" && break; sleep 0.01; done
realtime start > "$tmp/rt.log" 2>&1 || exit 1
B=hm2_7i92.0
halcmd loadrt hostmot2 || exit 1
halcmd loadrt hm2_eth board_ip="$ip" || { cat "$tmp/rt.log"; exit 1; }
halcmd loadrt threads name1=servo period1=1000000
halcmd loadrt sampler depth=$((cycles + 100)) cfg=sss
halcmd addf $B.read-request servo
halcmd addf $B.read servo
halcmd addf $B.write servo
halcmd addf sampler.0 servo
halcmd net rr $B.read-request.time sampler.0.pin.0
halcmd net rd $B.read.time sampler.0.pin.1
halcmd net wr $B.write.time sampler.0.pin.2
halcmd setp $B.watchdog.timeout_ns 100000000
halcmd setp $B.packet-error-limit 2147483647   # a loaded machine drops replies: count them, keep going
halcmd setp $B.stepgen.00.control-type 1
halcmd setp $B.stepgen.00.velocity-cmd 1000
halcmd setp $B.stepgen.00.enable 1
halcmd start
halsampler -n $cycles -c 0 > "$tmp/samples" || exit 1
halcmd stop
errors=$(halcmd getp $B.packet-error-total)
# pct FILE: p50, p99 and max (us) of the sorted ns values in FILE.
pct() {
    awk '{ v[NR] = $1 } END { printf "p50 %.1f us, p99 %.1f us, max %.1f us", v[int(NR * 0.50)] / 1000, v[int(NR * 0.99)] / 1000, v[NR] / 1000 }' "$1"
}
awk '{ print $1 + $2 + $3 }' "$tmp/samples" | sort -n > "$tmp/total"
awk '{ print $2 }' "$tmp/samples" | sort -n > "$tmp/read"
echo "hm2_eth: read-request+read+write per 1 ms cycle, $(wc -l < "$tmp/total") cycles, loopback to mesa-sim (7I92): $(pct "$tmp/total")"
echo "hm2_eth: read (waiting for the reply) alone: $(pct "$tmp/read"); replies lost (read timeout 80% of the period): $errors"
