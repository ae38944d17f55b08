#!/bin/bash
# Bad carousel module arguments fail the load with a message naming the problem.
for a in encoding=grey pockets=0 pockets=8 dir=3 "pockets=20 encoding=binary" \
    "pockets=100 encoding=bcd num_sense=7" "pockets=8 encoding=single num_sense=4" \
    "pockets=40 encoding=single" "pockets=8 num_sense=33" "pockets=8 encoding=gray,binary" \
    "pockets=6,6 dir=1,2,1" "pockets=99 encoding=bcd num_sense=8"; do
    echo "== $a"
    echo "load carousel $a" | "$EMC2_HOME/objects/unit/comptest"
done
