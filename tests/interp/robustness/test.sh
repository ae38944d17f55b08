#!/bin/bash
# Huge numbers and out-of-range integers give errors or exact output, never a crash.
rs274 -n 0 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
