#!/bin/bash
# Motion's pure pieces without HAL: trapezoid moves stay within their limits and land exactly,
# comp-table interpolation, cubic interpolation of a ramp, both comp-file types and bad files.
cd "$(dirname "$0")" || exit 1
exec "$EMC2_HOME/objects/unit/motion_pure_unit"
