#!/bin/bash
# From the sampled joint position: the largest change of velocity between two servo cycles
# must stay below what 50 units/s^2 allows with cubic interpolation (no step at each 4th cycle).
../common/drain-samples.sh | awk '
    NR > 1 { v = ($1 - p) / 0.001; if (NR > 2) { dv = v - lv; if (dv < 0) dv = -dv; if (dv > m) m = dv } lv = v }
    { p = $1 }
    END { printf "largest velocity change per cycle below 0.2 units/s: %s\n", (m < 0.2 ? "yes" : "no") }'
