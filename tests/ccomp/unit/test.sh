#!/bin/bash
# Cutter comp on straight paths: entry, convex corner arcs, concave trims, exit, queued calls.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/comp_unit" < cases.txt
