#!/bin/bash
# Kinematics edge values through the fake-HAL harness: the Newton forward solvers give up (-5) after
# 1000 steps per call even when limit-iterations is higher and nothing converges (a failure leaves the counts).
cd "$(dirname "$0")"
for s in genhex penta; do
    echo "== $s"
    "$EMC2_HOME/objects/unit/comptest" < $s.script
done
