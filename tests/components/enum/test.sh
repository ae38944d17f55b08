#!/bin/bash
# enum: spec errors, decode and encode channels, skipped (empty) values, names=.
for args in "" "enums=X;a" "enums=D" "enums=D;;" "enums=D;a,E;b names=x" \
            "enums=D;a_label_that_is_far_too_long_for_one_hal_pin_name"; do
    echo "== $args"
    echo "load enum $args" | "$EMC2_HOME/objects/unit/comptest"
done
echo "== decode and encode"
"$EMC2_HOME/objects/unit/comptest" <<'SCRIPT'
load enum enums=D;zero;one;;three,E;;red;green
show
functs enum.0.decode enum.1.encode
set enum.0.input 3
cycle
get enum.0.zero-out enum.0.one-out enum.0.three-out
set enum.0.input 1
cycle
get enum.0.zero-out enum.0.one-out enum.0.three-out
set enum.0.one-val 7
cycle
get enum.0.zero-out enum.0.one-out enum.0.three-out
cycle
get enum.1.output
set enum.1.green-in 1
cycle
get enum.1.output
set enum.1.red-in 1
cycle
get enum.1.output
SCRIPT
echo "== names"
printf 'load enum enums=D;a;b names=mode\nshow\n' | "$EMC2_HOME/objects/unit/comptest"
