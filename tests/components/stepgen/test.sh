#!/bin/bash
# stepgen: load errors, pins of each step type, and a short position-mode move.
for s in script-noconf script-badctrl script-types script-move; do
    echo "== $s"
    "$EMC2_HOME/objects/unit/comptest" < $s
done
