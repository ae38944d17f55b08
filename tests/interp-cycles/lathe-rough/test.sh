#!/bin/bash
# G71/G72 roughing and G70 finishing of profile subroutines: levels, crossings on lines and arcs, allowances.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
