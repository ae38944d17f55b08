#!/bin/bash
# Tool table loading, TOOL_CHANGE_QUILL_UP/AT_G30, RETAIN_G43, tool changes, G43/G43.1/G43.2/G49 and G10 L1/L10/L11.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
s1=${PIPESTATUS[0]}; [ "$s1" = 0 ] || exit "$s1"
rs274 -i change.ini -t test.tbl -g change.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
