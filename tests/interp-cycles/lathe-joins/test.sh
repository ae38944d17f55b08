#!/bin/bash
# G70/G71 offset joins: programmed points kept at zero allowance, near-tangent joins at the first crossing, no slivers at corner arc tops.
rs274 -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
