#!/bin/bash
# Polar words in repeated canned cycles (G91 ^60 L6 goes around the circle) and the cycle
# initial level, which is taken again whenever the motion mode changes.
rs274 -g test.ngc 2>&1 | awk '{$1=""; print}' | grep -v 'MOTION_CONTROL\|NAIVECAM'
exit "${PIPESTATUS[0]}"
