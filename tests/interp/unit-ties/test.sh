#!/bin/bash
# Stored lengths (tool table, parameters) converted to program units with LinuxCNC's arithmetic, so ties at the last printed digit round alike.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
