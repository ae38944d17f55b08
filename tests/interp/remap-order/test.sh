#!/bin/bash
# Remapped F, S, T, M (groups 5-10) and G codes run in the execution order of gcode.md §3 whatever their
# order on the line; inside its own procedure F, S or T is the built-in one; errors reset the levels.
rs274 -i test.ini -t test.tbl -g test.ngc 2>&1 | sed 's/^ *[0-9]* N/N/' || exit 1
rs274 -i test.ini -n 0 -g errors.ngc 2>&1 | sed 's/^ *[0-9]* N/N/'
exit "${PIPESTATUS[0]}"
