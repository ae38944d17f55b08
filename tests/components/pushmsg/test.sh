#!/bin/bash
# pushmsg: messages on trigger edges with pin values substituted, edge inversion, force, enable,
# and every load-time check of the msgs= entries.
run() { "$EMC2_HOME/objects/unit/comptest" | grep -v '^hal_init'; }
echo "== two messages, placeholders of each type, a backslash keeps its brace"
run <<'S'
load pushmsg "msgs=e|oil|Oil\{low} {f:level} bar {s:n} end {u:q},E|spin|speed {u:rpm} and {k:count}"
show
functs pushmsg
set pushmsg.oil.level 1.5
set pushmsg.oil.n -3
cycle 1
set pushmsg.oil.trigger 1
cycle 2
set pushmsg.spin.rpm 1200
set pushmsg.spin.count 12345678901
set pushmsg.spin.trigger 1
cycle 1
echo edge TRUE inverts the trigger: prints when it falls
set pushmsg.spin.edge 1
cycle 1
set pushmsg.spin.trigger 0
cycle 1
echo disabled: triggers are ignored, force still prints
set pushmsg.enable 0
set pushmsg.oil.trigger 0
cycle 1
set pushmsg.oil.trigger 1
cycle 1
set pushmsg.oil.force 1
cycle 1
S
for bad in "" "e|ab" "x|a|b" "ee|a|b" "e|ab|" "e|a b|x" "e|this-pin-name-is-far-far-too-long-for-hal|x" \
           "e|a|x {f:v" "e|a|x {f}" "e|a|x {fv}" "e|a|x {z:v}" "e|a|x {f:b c}" "e|a|x,e|a|y"; do
    echo "== msgs=$bad"
    echo "load pushmsg \"msgs=$bad\"" | run
done
