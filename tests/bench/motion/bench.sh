#!/bin/bash
# Motion benchmark: SET_LINE commands reaching the planner per second through the command ring at
# a 1 kHz servo thread, and motion-controller / motion-command-handler time per cycle (p50,
# p99, p99.99, max over 30,000 cycles) with 9 joints jogging and homing.
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
. "$top/scripts/rip-environment" >/dev/null 2>&1
export OPENEMC_INSTANCE=${OPENEMC_INSTANCE:-201}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'realtime stop >/dev/null 2>&1; rm -rf "$work"' EXIT
realtime stop >/dev/null 2>&1
realtime start 2>/dev/null || exit 1
{
    echo "loadrt trivkins coordinates=xyzabcuvw"
    echo "loadrt tpmod"
    echo "loadrt homemod"
    echo "loadrt motmod num_joints=9"
    echo "addf motion-command-handler servo-thread"
    echo "addf motion-controller servo-thread"
    for j in $(seq 0 8); do echo "net j$j joint.$j.motor-pos-cmd => joint.$j.motor-pos-fb"; done
    echo "loadrt sampler depth=40000 cfg=ss"
    echo "net tctl motion-controller.time => sampler.0.pin.0"
    echo "net tcmd motion-command-handler.time => sampler.0.pin.1"
    echo "setp sampler.0.enable 0"
    echo "addf sampler.0 servo-thread"
    echo "start"
} >"$work/bench.hal"
halcmd -f "$work/bench.hal" || exit 1
{
    for j in $(seq 0 8); do
        echo "SET_JOINT_VEL_LIMIT joint=$j vel=20"
        echo "SET_JOINT_ACC_LIMIT joint=$j acc=200"
        echo "SET_JOINT_MAX_FERROR joint=$j max_ferror=100"
        echo "SET_JOINT_MIN_FERROR joint=$j min_ferror=100"
        echo "SET_JOINT_HOMING_PARAMS joint=$j home_sequence=$((j % 3)) home_final_vel=-1 home_offset=$j home=0"
        echo "SET_AXIS_VEL_LIMIT axis=$j vel=100"
        echo "SET_AXIS_ACC_LIMIT axis=$j acc=1000"
    done
} >"$work/setup.inj"
motion-inject "$work/setup.inj" || exit 1
"$top/objects/unit/motion_ring_bench" || exit 1
{
    echo "FREE"
    echo "wait motion_state == 1"
    echo "sh halcmd setp sampler.0.enable 1"
    for round in 1 2 3 4 5 6 7 8; do
        for j in $(seq 0 8); do echo "JOG_CONT joint=$j vel=$(( (round % 2) * 2 - 1 ))0"; done
        echo "sleep 1"
        for j in $(seq 0 8); do echo "JOG_ABORT joint=$j"; done
        echo "wait inpos == 1"
        echo "JOINT_HOME joint=-1"
        echo "wait homing_active == 0 10"
        echo "wait teleop == 1"
        echo "FREE"
        echo "wait motion_state == 1"
    done
} >"$work/work.inj"
motion-inject -t 20 "$work/work.inj" >/dev/null || echo "motion bench: workload script failed" >&2
halcmd stop
timeout 5 halsampler -n 30000 >"$work/times" || true
for col in 1 2; do
    name=$([ $col = 1 ] && echo motion-controller || echo motion-command-handler)
    awk -v c=$col '{ print $c }' "$work/times" | sort -n | awk -v name="$name" '
        { v[NR] = $1 }
        END { if (NR == 0) { print "motion: no samples"; exit }
              printf "motion: %s per cycle, 9 joints jogging/homing, %d cycles: p50 %d ns, p99 %d ns, p99.99 %d ns, max %d ns\n",
                     name, NR, v[int(NR * 0.5) + 1], v[int(NR * 0.99) + 1], v[int(NR * 0.9999) + 1], v[NR] }'
done
