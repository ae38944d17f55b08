#!/bin/bash
# halcmd benchmark: -f load time of a generated 10,000-line HAL file, HAL memory per signal and pin.
set -e
TOP=$(cd "$(dirname "$0")/../../.." && pwd)
. "$TOP/scripts/rip-environment"
export OPENEMC_INSTANCE=${OPENEMC_INSTANCE:-$((200 + $$ % 50))}
TMP=$(mktemp -d)
trap 'realtime stop > /dev/null 2>&1 || true; rm -rf "$TMP"' EXIT

# Print the "used" figure of `halcmd status mem`.
mem_used() { halcmd status mem | sed -n 's|.*used/total shared memory: *\([0-9]*\)/.*|\1|p'; }

N=2500
for i in $(seq 1 $N); do
    echo "newsig s$i float"
    echo "sets s$i $i.5"
    echo "newsig b$i bit"
    echo "sets b$i 1"
done > "$TMP/bench.hal"
realtime start 2> /dev/null
before=$(mem_used)
start=$(date +%s%N)
halcmd -f "$TMP/bench.hal"
end=$(date +%s%N)
after=$(mem_used)
lines=$(wc -l < "$TMP/bench.hal")
echo "halcmd -f: $lines lines in $(( (end - start) / 1000000 )) ms ($(( (end - start) / lines )) ns/line)"
echo "memory per signal: $(( (after - before) / (2 * N) )) bytes"
before=$(mem_used)
halcmd loadrt and2 count=1000
after=$(mem_used)
pins=$(halcmd list pin 'and2.*' | wc -w)
echo "memory per pin (and2, incl. functs/params): $(( (after - before) / pins )) bytes ($pins pins)"
