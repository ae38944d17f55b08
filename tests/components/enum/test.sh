#!/bin/bash
# enum: load errors, decode and encode instances, empty fields that use up a value, names=.
for args in "" "enums=X;a" "enums=Da" "enums=D" "enums=D;;" "enums=D;a,E;b names=x" "enums=D;a names=x,y" \
            "enums=D;a_label_that_is_far_too_long_for_one_hal_pin_name"; do
    echo "== $args"
    echo "load enum $args" | "$EMC2_HOME/objects/unit/comptest"
done
echo "== decode and encode"
"$EMC2_HOME/objects/unit/comptest" <<'SCRIPT'
load enum enums=D;zero;one;;three;,E;;red;green;;blue
show
functs enum-decode.00 enum-encode.01
echo decoder: input 3, 1, then one-val moved to 3 (two states TRUE)
set enum-decode.00.input 3
cycle
get enum-decode.00.zero-out enum-decode.00.one-out enum-decode.00.three-out
set enum-decode.00.input 1
cycle
get enum-decode.00.zero-out enum-decode.00.one-out enum-decode.00.three-out
set enum-decode.00.one-val 3
set enum-decode.00.input 3
cycle
get enum-decode.00.zero-out enum-decode.00.one-out enum-decode.00.three-out
echo encoder: none TRUE gives 0, the last TRUE state wins
cycle
get enum-encode.01.output
set enum-encode.01.green-in 1
cycle
get enum-encode.01.output
set enum-encode.01.red-in 1
cycle
get enum-encode.01.output
set enum-encode.01.blue-in 1
cycle
get enum-encode.01.output
set enum-encode.01.green-in 0
set enum-encode.01.blue-in 0
cycle
get enum-encode.01.output
SCRIPT
echo "== names"
printf 'load enum enums=D;a;b,e;c names=mode,sel\nshow\n' | "$EMC2_HOME/objects/unit/comptest"
