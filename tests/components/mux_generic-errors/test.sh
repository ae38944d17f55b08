#!/bin/bash
# mux_generic rejects a missing config, bad type letters and bad sizes.
for args in "" "config=bx4" "config=bb0" "config=ff1025" "config=bb"; do
    echo "== $args"
    echo "load mux_generic $args" | "$EMC2_HOME/objects/unit/comptest"
done
