#!/bin/bash
# mux_generic config letters and digits in any order; one letter means the same output type; sizes cap at 1024.
for args in "config=b2b" "config=f5f" "config=8u" "config=s3f"; do
    echo "== $args"
    printf 'load mux_generic %s\nshow\n' "$args" | "$EMC2_HOME/objects/unit/comptest"
done
echo "== config=ff1030: inputs made, last input"
printf 'load mux_generic config=ff1030\nshow\n' | "$EMC2_HOME/objects/unit/comptest" > pins.out
grep -c 'in-float-' pins.out
grep 'in-float-' pins.out | tail -1
rm -f pins.out
