#!/bin/bash
# Every sample: motor-pos-cmd = pos-cmd + backlash-filt; the filtered correction moves at most
# 5 units/s (half of 10) and changes speed by at most 50 units/s^2 (half of 100); the slack
# covers the 6 decimals of the samples.
halsampler -n 138 | awk '
    { if (($2 - $1 - $3) > 1e-9 || ($1 + $3 - $2) > 1e-9) bad++
      if (NR > 1) { v = ($3 - f) / 0.001; if (v > 5.002 || v < -5.002) fast++
                    if (NR > 2 && ((v - lastv) / 0.001 > 53 || (lastv - v) / 0.001 > 53)) jerk++; lastv = v }
      f = $3; if ($4 > maxc) maxc = $4; if ($4 < minc) minc = $4 }
    END { printf "motor = pos + filt: %s\n", bad ? "no" : "yes"
          printf "correction targets: %.3f %.3f\n", maxc, minc
          printf "filter within half velocity: %s, within half acceleration: %s\n", fast ? "no" : "yes", jerk ? "no" : "yes" }'
