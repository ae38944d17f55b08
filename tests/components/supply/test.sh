#!/bin/bash
# supply: channel limits, pin names with a leading underscore (_q starts TRUE), d and value as
# I/O pins, and the update funct.
for args in "num_chan=0" "num_chan=9"; do
    echo "== $args"
    echo "load supply $args" | "$EMC2_HOME/objects/unit/comptest"
done
echo "== num_chan=2"
"$EMC2_HOME/objects/unit/comptest" <<'SCRIPT'
load supply num_chan=2
show
functs supply.0.update supply.1.update
set supply.0.d 1
set supply.0.value 2.5
set supply.1.value -4
cycle
get supply.0.q supply.0._q supply.0.variable supply.0._variable
get supply.1.q supply.1._q supply.1.variable supply.1._variable
SCRIPT
