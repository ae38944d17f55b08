#!/bin/bash
# The long random sweep of the planner: 100,000 random move chains with random limits, every servo
# sample checked (tests/tp/tp-random runs 2,000 of them in make check).
set -e
TOP=$(cd "$(dirname "$0")/../../.." && pwd)
make -C "$TOP" -s objects/unit/tp_random
exec "$TOP/objects/unit/tp_random" "${TP_RANDOM_CHAINS:-100000}"
