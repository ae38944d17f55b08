#!/bin/bash
# moveoff refuses joint counts outside 1..16; without personality it has 3 joints.
for args in "personality=17" "personality=0" "personality=-1" "names=a,b personality=2,40"; do
    echo "== $args"
    echo "load moveoff $args" | "$EMC2_HOME/objects/unit/comptest"
done
echo "== default"
printf 'load moveoff\nget moveoff.0.pos-2\nget moveoff.0.pos-3\n' | "$EMC2_HOME/objects/unit/comptest"
echo "== 16 joints"
printf 'load moveoff personality=16\nget moveoff.0.offset-vel-15\n' | "$EMC2_HOME/objects/unit/comptest"
