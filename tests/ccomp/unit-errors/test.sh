#!/bin/bash
# Cutter comp geometry errors: short entry, arc exit, tool larger than an inside arc, concave gouges.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/comp_unit" < cases.txt
