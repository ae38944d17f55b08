#!/bin/bash
# REMAP= of M and G codes to NGC procedures: named and positional arguments, a missing required word
# reported with the generated call line, and levels back at 0 after the error.
rs274 -i test.ini -n 0 -g test.ngc 2>&1 | sed 's/^ *[0-9]* N/N/'
exit "${PIPESTATUS[0]}"
