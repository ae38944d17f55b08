#!/bin/bash
# EXISTS[] of named (local, global, predefined), numbered and indirect parameters.
rs274 -g test.ngc | awk '{$1=""; print}' | grep MESSAGE
exit "${PIPESTATUS[0]}"
