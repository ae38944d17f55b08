#!/bin/bash
# Launcher benchmark: linuxcnc -r start to display (task ready) and display exit to launcher exit,
# with the launcher-test stand-in as [TASK]TASK (no motion stack), best of 5.
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
. "$top/scripts/rip-environment" >/dev/null 2>&1
export OPENEMC_INSTANCE=${OPENEMC_INSTANCE:-202}
export PATH=$PATH:$top/tests/launcher/doubles
cd "$(dirname "$0")" || exit 1
best_start=999 best_stop=999
for run in 1 2 3 4 5; do
    rm -f ready.time
    t0=$(date +%s.%N)
    linuxcnc -r bench.ini > /dev/null 2>&1 || { echo "launcher: run failed" >&2; exit 1; }
    t2=$(date +%s.%N)
    t1=$(cat ready.time)
    best_start=$(awk -v a="$best_start" -v b="$(awk -v x="$t0" -v y="$t1" 'BEGIN{print y-x}')" 'BEGIN{print (b<a)?b:a}')
    best_stop=$(awk -v a="$best_stop" -v b="$(awk -v x="$t1" -v y="$t2" 'BEGIN{print y-x}')" 'BEGIN{print (b<a)?b:a}')
done
rm -f ready.time task-record.txt
awk -v s="$best_start" -v t="$best_stop" 'BEGIN { printf "launcher: start to display %.3f s, display exit to clean exit %.3f s (best of 5; stand-in task, no motion stack)\n", s, t }'
