#!/bin/bash
# HAL threads inside rtapi_app: creation rules, addf/initf/delf, init cycle vs threadbeat, parked thread, unload.
out=$(mktemp)
. ../../lib/testmods.sh
trap 'tm_cleanup; rm -f "$out"' EXIT
realtime start 2>"$out" || exit 1
halcmd loadrt hal_core_rt || exit 1
halcmd start
# poll (no time limit assertion) until the fast thread has run a few cycles
for i in $(seq 1 3000); do
    beat=$(halcmd getp fast.threadbeat)
    [ "$beat" -ge 20 ] && break
    sleep 0.01
done
halcmd stop
for p in init-calls init-saw mismatch period; do
    echo "$p=$(halcmd getp hal-core-rt.$p)"
done
[ "$(halcmd getp hal-core-rt.count)" -ge 20 ] && echo "count ok"
[ "$(halcmd getp hal-core-rt.d-count)" -gt 0 ] && echo "parked thread mid still runs"
# the executed init list is freed by the thread once it finds the HAL mutex free
for i in $(seq 1 500); do
    users=$(halcmd show funct hal-core-rt.init | awk 'NR>2 && NF {print $5}')
    [ "$users" = 0 ] && break
    sleep 0.01
done
echo "init users $users"
halcmd show thread | sed 's/( *[0-9]*, *[0-9]* )//'
# unloading the creator removes the pseudo comps (and so the header lines); threads stay
halcmd unloadrt hal_core_rt
halcmd show thread | sed 's/( *[0-9]*, *[0-9]* )//'
halcmd list comp | sed 's/halcmd[0-9]*/halcmd/'
grep -E '^(T:|HAL)' "$out"
