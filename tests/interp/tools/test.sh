#!/bin/bash
# Tool table loading, tool changes, G43/G43.1/G43.2/G49 and G10 L1/L10/L11.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
