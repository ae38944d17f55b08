#!/bin/bash
# Drilling cycles G81/G82/G83/G73/G85/G86/G89 in XY: positioning, G98/G99, G90/G91, L repeats, sticky words.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/cycles_unit" < cases.txt
