#!/bin/bash
# overrun-stop: periods no machine can run are refused; a thread that overruns every cycle
# (20 us of work each 1 us) still lets halcmd, unload and realtime stop through.
. "$(dirname "$0")/../../lib/testmods.sh"
out=$(mktemp)
trap 'timeout 60 realtime stop >/dev/null 2>&1; tm_cleanup; rm -f "$out"' EXIT
realtime start 2>"$out" || exit 1
# t CMD...: run a command with a time limit; says so when it hangs
t() {
    timeout 30 "$@"
    local rc=$?
    [ $rc = 124 ] && echo "HANG: $*"
    return $rc
}
t halcmd loadrt threads period1=10 2>/dev/null; echo "period1=10 -> $?"
t halcmd loadrt threads name1=slow period1=999 2>/dev/null; echo "period1=999 -> $?"
t halcmd loadrt threads name1=spin period1=1000; echo "period1=1000 -> $?"
t halcmd loadrt busy_rt
t halcmd addf busy.spin spin
t halcmd start
# wait (no time limit assertion) until the thread has fallen behind
for i in $(seq 1 1000); do
    [ "$(t halcmd getp spin.threadbeat)" -ge 100 ] && break
    sleep 0.01
done
t halcmd show funct busy.spin | awk 'NR>2 && NF {print $NF, "users", $5}'
t halcmd stop; echo "stop -> $?"
t halcmd start; echo "start -> $?"
t halcmd unloadrt busy_rt; echo "unloadrt -> $?"
t halcmd addf busy.spin spin 2>/dev/null; echo "addf after unload -> $?"
t halcmd loadrt busy_rt; t halcmd addf busy.spin spin; echo "addf again -> $?"
t realtime stop; echo "realtime stop -> $?"
realtime status; echo "status -> $?"
grep -E '^HAL: ERROR|^THREADS' "$out"
