#!/bin/bash
# Kinematics edge values through the fake-HAL harness: the Newton forward solvers stop
# after 1000 steps per attempt even when limit-iterations is higher and nothing converges.
cd "$(dirname "$0")"
for s in genhex penta; do
    echo "== $s"
    "$EMC2_HOME/objects/unit/comptest" < $s.script
done
