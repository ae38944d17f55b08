#!/bin/bash
# Canned-cycle error paths: missing or sticky words, bad R/Z order, Q, L, rotary words, spindle state.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/cycles_unit" < cases.txt
