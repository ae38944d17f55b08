#!/bin/bash
# Numbered/named parameters, scoping, subroutine arguments, predefined names.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
