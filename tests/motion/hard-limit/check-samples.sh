#!/bin/bash
# Samples are "switch amp-enable": the amplifier may never be enabled in a cycle the switch is on,
# except while the override mask is in force (the rows after OVERRIDE_LIMITS), and the switch must
# have been seen on with the amplifier off at least once (the fault cycle).
../common/drain-samples.sh | awk '
    $1 == 1 && $2 == 0 { off++ }
    $1 == 1 && $2 == 1 { on++ }
    prev == "0 1" && $0 ~ /^1 / { trip = $2 }
    { prev = $1 " " $2 }
    END {
        printf "switch on with amplifier off: %s\n", (off > 0 ? "yes" : "no")
        printf "amplifier in the first cycle the switch was seen: %d\n", trip
        printf "switch on with amplifier on (override): %s\n", (on > 0 ? "yes" : "no")
    }'
