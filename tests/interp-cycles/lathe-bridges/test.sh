#!/bin/bash
# G71.1 bridges over pockets: which element starts get their feed (LinuxCNC: none from the flat run
# before a pocket whose bridge lands inside an arc; all of them when it lands inside a line).
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
