#!/bin/bash
# Without -g the menu on stderr is used: 4 toggles block delete, 1 starts.
printf '4\n1\n' | rs274 test.ngc 2>&1 | grep -E 'block delete|TRAVERSE|^executing'
exit "${PIPESTATUS[1]}"
