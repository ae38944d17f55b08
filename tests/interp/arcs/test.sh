#!/bin/bash
# G2/G3 in G17/G18/G19, center and radius formats, G90.1, helix P turns, inverse-time arc feed.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
