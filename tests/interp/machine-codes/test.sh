#!/bin/bash
# Spindle, coolant, overrides, I/O, feed modes, path control, stops, G33, probing, G7, polar words.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
