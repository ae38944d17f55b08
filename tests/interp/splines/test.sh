#!/bin/bash
# G5/G5.1 splines and G5.2/G5.3 NURBS blocks: NURBS_G5_FEED (4 points for G5, 3 for G5.1), the debug lines, the current point after each.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
