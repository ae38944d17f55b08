#!/bin/bash
# sim_matrix_kb: config sizes and names, and the refusal of bad ones.
run() { echo "== $*"; printf '%s\n' "load sim_matrix_kb $*" show | "$EMC2_HOME/objects/unit/comptest"; }
run "config=1x2,3x3 names=a,b"
run names=pad
for a in config=9x1 config=2x0 config=2x2s config=22 "config=1x1,1x1 names=a" \
         names=a,b "names=abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyz"; do
    run "$a"
done
