#!/bin/bash
# Drilling and boring cycles in G18 (ZX) and G19 (YZ), G86/G87/G88 spindle handling, G7 X halving.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
