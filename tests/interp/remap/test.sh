#!/bin/bash
# REMAP= of M and G codes to NGC procedures: named and positional arguments, modal G remap.
rs274 -i test.ini -n 0 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
