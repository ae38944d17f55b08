#!/bin/bash
# O-word flow: if/elseif/else, while, do, repeat, break, continue, recursion, subs on the path and after M2.
rs274 -i test.ini -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
