#!/bin/bash
# Cutter comp on straight moves: entry, convex corner arcs, concave trims, G41/G42, D words, queued calls, exit.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
