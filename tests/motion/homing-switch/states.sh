#!/bin/bash
# The home-state values each joint went through, consecutive repeats folded.
../common/drain-samples.sh | awk '
    NR == 1 { for (j = 1; j <= 3; j++) last[j] = -1 }
    { for (j = 1; j <= 3; j++) if ($j != last[j]) { seq[j] = seq[j] " " $j; last[j] = $j } }
    END { for (j = 1; j <= 3; j++) printf "joint %d states:%s\n", j - 1, seq[j] }'
