#!/bin/bash
# Pins the reference's rotated STRAIGHT_FEED coordinates of G84/G74 tapping feeds in G18 and G19.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
