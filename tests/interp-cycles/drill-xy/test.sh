#!/bin/bash
# G81 G82 G83 G73 G85 G89 in XY: G98/G99 retract, G90/G91, L repeats, sticky R/Z/P/Q, exact-path bracket.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
