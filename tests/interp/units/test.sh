#!/bin/bash
# Unit switching converts the position and offsets but not stored parameters.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
