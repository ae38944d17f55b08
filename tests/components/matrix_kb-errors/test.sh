#!/bin/bash
# matrix_kb refuses a missing or malformed config= and a names= list of the wrong length.
for a in "" config=9x2 config=0x3 config=4x3q config=4-3 config=4x config=4x3s,2x22 \
         "config=2x2,3x3 names=a" "config=2x2 names=abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyz"; do
    echo "== $a"
    echo "load matrix_kb $a" | "$EMC2_HOME/objects/unit/comptest"
done
