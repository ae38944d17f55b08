#!/bin/bash
# Cutter comp with arcs: arc entry, line-arc and arc-arc corners, inside/outside arcs, helix, inverse time.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
