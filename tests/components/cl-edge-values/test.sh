#!/bin/bash
# ClassicLadder edge values: POW past 64 and to 2^31-1 wraps like 32-bit multiplication,
# and counters written to the s32 limits count up/down without signed overflow.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/cl_sim" < script
