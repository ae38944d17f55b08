#!/bin/bash
# killed-usercomp: a user component whose process was killed (no hal_exit) is removed by
# unload / unloadusr (with a warning), its pins leave their signals, waitusr returns.
realtime start 2> /dev/null || exit 1
trap 'realtime stop' EXIT
UC="$EMC2_HOME/objects/unit/halcmd_usercomp"
# lc: the user components and their pins, without halcmd's own
lc() { echo "comps: $(halcmd list comp | tr ' ' '\n' | grep -v '^halcmd' | grep -v '^$' | sort | tr '\n' ' ')"; }
halcmd loadusr -Wn k1 "$UC" k1
halcmd loadusr -Wn k2 "$UC" k2
halcmd loadusr -Wn k3 "$UC" k3
halcmd net s1 k1.out
for c in k1 k2 k3; do
    kill -KILL "$(halcmd show comp $c | awk '$2 == "User" {print $(NF-1)}')"
done
sleep 0.2
lc
echo "> unload k1 (linked to s1)"
halcmd unload k1 2>&1 | sed -E "s/process [0-9]+/process PID/"
lc
echo "s1 pins: $(halcmd show sig s1 | grep -c 'k1.out')"
echo "> unloadusr all"
halcmd unloadusr all 2>&1 | sed -E "s/process [0-9]+/process PID/" | sort
lc
echo "> waitusr of a killed component returns"
halcmd loadusr -Wn k4 "$UC" k4
kill -KILL "$(halcmd show comp k4 | awk '$2 == "User" {print $(NF-1)}')"
timeout 20 halcmd waitusr k4; echo "waitusr -> $?"
echo "> a live component still gets SIGTERM and leaves by itself"
halcmd loadusr -Wn k5 "$UC" k5
halcmd unload k5 2>&1
timeout 20 halcmd waitusr k5; echo "waitusr -> $?"
lc
