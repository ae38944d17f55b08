#!/bin/bash
# G76 threading: pass depths with degression, compound angle, spring passes, exit taper, internal thread.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
