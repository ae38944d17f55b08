#!/bin/bash
# Lathe (G18) cutter comp: nose-radius paths shifted to the imaginary tip by tool orientation, G41 and G42.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
