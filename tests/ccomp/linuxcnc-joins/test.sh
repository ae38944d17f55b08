#!/bin/bash
# Cutter comp joins as LinuxCNC computes them: re-entry after G40, reversals, rounded arc ends, negative diameters, lathe arc entry.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
