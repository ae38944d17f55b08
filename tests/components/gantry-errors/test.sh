#!/bin/bash
# gantry: the personality (joint count) must be 1 to 7; the default is 2 joints.
for a in personality=0 personality=-1 personality=8 ""; do
    echo "== $a"
    printf 'load gantry %s\nshow\n' "$a" | "$EMC2_HOME/objects/unit/comptest" | grep -v '^pin\|^param\|^funct'
done
printf 'load gantry\nshow\n' | "$EMC2_HOME/objects/unit/comptest" | grep -c 'pos-cmd'
