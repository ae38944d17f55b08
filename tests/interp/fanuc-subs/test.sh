#!/bin/bash
# Fanuc-style M98 P/L calls of O-numbered subprograms ending in M99, nested, globals shared.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
