#!/bin/bash
# Comments and active comments: MSG, DEBUG, PRINT, LOG*, formats and expansion.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
