#!/bin/bash
# Planner figures: tp-bench's generated programs fed to the library as segments (trapezoid and
# S-curve at jerk 2e5), segments planned per CPU second, planner CPU per servo cycle on a
# 150,000-segment program.  Figures only; nothing here fails on a slow machine.
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
bench="$top/objects/unit/tp_bench"
echo "tp: tp-bench programs offline, trapezoid (1 kHz, 500 mm/s, 5000 mm/s^2)"
"$bench" programs | sed 's/^/tp: /'
echo "tp: tp-bench programs offline, S-curve, jerk 200000 mm/s^3"
"$bench" programs --jerk 200000 | sed 's/^/tp: /'
"$bench" throughput | sed 's/^/tp: /'
"$bench" throughput --jerk 200000 | sed 's/^/tp: /'
"$bench" cycle-cpu | sed 's/^/tp: /'
"$bench" cycle-cpu --jerk 200000 | sed 's/^/tp: /'
exit 0
