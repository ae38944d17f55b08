#!/bin/bash
# Kinematics modules under motmod: their pins exist, motion runs their maps (a teleop jog moves
# the joints), and switchable ones follow motion.switchkins-type (a bad type is reported).
log=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$log" "$log.hal"' EXIT
run() {
    local kins=$1 joints=$2 args=$3
    halrun -U >/dev/null 2>&1
    {
        echo "setexact_for_test_suite_only"
        echo "loadrt $kins $args"
        echo "source ../common/planner.hal"
        echo "loadrt motmod num_joints=$joints"
        echo "addf motion-command-handler servo-thread"
        echo "addf motion-controller servo-thread"
        for j in $(seq 0 $((joints - 1))); do echo "net j$j joint.$j.motor-pos-cmd => joint.$j.motor-pos-fb"; done
        echo "start"
    } >"$log.hal"
    halcmd -f "$log.hal" >>"$log" 2>&1
    for _ in $(seq 50); do halcmd getp motion.in-position >/dev/null 2>&1 && break; sleep 0.1; done
    echo "== $kins: pins $(halcmd -s show pin | awk -v k="$kins" '$1 == k { n++ } END { print n + 0 }')"
}
jog() {
    for j in $(seq 0 $(($1 - 1))); do
        echo "SET_JOINT_HOMING_PARAMS joint=$j home_sequence=0 home_final_vel=-1"
    done | motion-inject -
    motion-inject - <<'INJ'
ENABLE
FREE
wait enabled == 1
JOINT_HOME joint=-1
wait teleop == 1
JOG_INCR joint=-1 axis=0 vel=1 offset=0.25
cycles 3
wait axis.0.teleop_jogging == 0
status carte_pos_cmd.x carte_pos_cmd.z joint.0.pos_cmd joint.2.pos_cmd
INJ
}
run xyzac-trt-kins 5 coordinates=xyzac
jog 5
halcmd setp motion.switchkins-type 1
sleep 0.2
echo "kinstype.is-1: $(halcmd getp kinstype.is-1)"
halcmd setp motion.switchkins-type 7
sleep 0.2
motion-inject - <<<"messages"
run millturn 5
jog 5
run xyzab_tdr_kins 5
jog 5
run xyzacb_trsrn 6
jog 6
halcmd -s show pin | awk '$1 == "motmod" && $5 == "motion.switchkins-type" { print "motion.switchkins-type", $2, $3 }'
