#!/bin/bash
# G10 L10 and L20 with an active XY rotation, and G43 applying a tool offset under rotation.
rs274 -g test.ngc | awk '{$1=""; print}' | sed 's/-0\.0000/0.0000/g'
exit "${PIPESTATUS[0]}"
