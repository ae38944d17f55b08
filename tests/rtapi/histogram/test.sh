#!/bin/bash
# Latency histogram: exact rows for known samples, then latency-histogram on real threads
# whose rows must add up to the sample count and whose bad options are refused.
top=${EMC2_HOME:-$(cd ../../.. && pwd)}
"$top/objects/unit/latency_hist_unit"
export PATH=$top/bin:$PATH
latency-histogram --bin 15 -t 0.1 >/dev/null 2>err.txt; echo "bin 15 -> $? $(cat err.txt)"
latency-histogram --bin >/dev/null 2>err.txt; echo "bin missing -> $? $(cat err.txt)"
rm -f err.txt
latency-histogram -t 0.3 --bin 5000 1ms > hist.txt 2>/dev/null
awk '/^servo +[0-9]/ { samples = $3 }
     / ns +[0-9]+/ { for (i = 1; i <= NF; i++) if ($i == "ns") { sum += $(i + 1); break } }
     /thread \(period/ { sections++ }
     END { print "sections", sections, "rows add up", (sum == samples && samples > 0 ? "yes" : "no") }' hist.txt
rm -f hist.txt
