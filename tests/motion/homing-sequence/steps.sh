#!/bin/bash
# In-step check of the last Home-All run: for each homing move (search 7, backoff 10, latch 12,
# final move 21), how many cycles after joint 0 joint 1 started it; joint 2 (sequence 2) must
# start after the group finished.
../common/drain-samples.sh | awk '
    { for (j = 1; j <= 3; j++) { if ($j != last[j] && $j != 0) at[j, $j] = NR; last[j] = $j } }
    END {
        split("7 10 12 21", states, " ")
        for (i = 1; i <= 4; i++) {
            s = states[i]
            printf "state %d: joint 1 starts %d cycles after joint 0\n", s, at[2, s] - at[1, s]
        }
        printf "joint 2 searched after the group finished: %s\n", (at[3, 7] > at[1, 21] && at[3, 7] > at[2, 21]) ? "yes" : "no"
    }'
