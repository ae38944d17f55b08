#!/bin/bash
# Cutter comp with arcs: arc entry, line-arc and arc-arc corners (convex and concave), helix Z, XZ lathe tips.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/comp_unit" < cases.txt
