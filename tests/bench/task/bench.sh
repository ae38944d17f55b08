#!/bin/bash
# Task benchmark on the sim mill with the whole motion stack (motmod, tpmod, milltask):
# linuxcnc -r start to machine ready (display started) and display exit to clean exit, best
# of 5; MDI commands per second through linuxcnc.command().mdi() + wait_complete().
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
. "$top/scripts/rip-environment" >/dev/null 2>&1
export OPENEMC_INSTANCE=${OPENEMC_INSTANCE:-207}
cd "$(dirname "$0")" || exit 1
cp ../../task/startup/tool.tbl.in tool.tbl
best_start=999 best_stop=999
for run in 1 2 3 4 5; do
    rm -f ready.time
    t0=$(date +%s.%N)
    linuxcnc -r bench.ini > /dev/null 2>&1 || { echo "task: run failed" >&2; exit 1; }
    t2=$(date +%s.%N)
    t1=$(cat ready.time)
    best_start=$(awk -v a="$best_start" -v b="$(awk -v x="$t0" -v y="$t1" 'BEGIN{print y-x}')" 'BEGIN{print (b<a)?b:a}')
    best_stop=$(awk -v a="$best_stop" -v b="$(awk -v x="$t1" -v y="$t2" 'BEGIN{print y-x}')" 'BEGIN{print (b<a)?b:a}')
done
awk -v s="$best_start" -v t="$best_stop" 'BEGIN { printf "task: sim mill start to machine ready %.3f s (target <= 1 s), shutdown %.3f s (target <= 0.5 s), best of 5\n", s, t }'
linuxcnc -r mdi.ini 2>/dev/null | grep '^task:' || { echo "task: MDI benchmark failed" >&2; exit 1; }
rm -f ready.time tool.tbl test.var test.var.bak
