#!/bin/bash
# G84/G74 tapping: overrides off, spindle reversal and dwell, G98/G99, G18/G19 feed order as the reference.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
