#!/bin/bash
# mux_generic rejects a missing config, bad characters, a third type letter, a missing size or type, size 1.
for args in "" "config=bx4" "config=bb0" "config=bbb4" "config=bb" "config=4" "config=f1"; do
    echo "== $args"
    echo "load mux_generic $args" | "$EMC2_HOME/objects/unit/comptest"
done
