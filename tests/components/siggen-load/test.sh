#!/bin/bash
# siggen channel limits: num_chan=16 works, 17 fails, names= works, both fail.
for args in "num_chan=16" "num_chan=17" "names=a,b" "num_chan=2 names=a"; do
    echo "== $args"
    echo "load siggen $args" | "$EMC2_HOME/objects/unit/comptest"
done
