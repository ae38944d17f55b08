#!/bin/bash
# Random tool changer: the tool in P0 is loaded at start-up, M6 swaps spindle and pocket and
# the swap is saved; M61 and G10 L1 keep every tool.
. ../lib/run-machine.sh
run_machine || exit 1
echo "saved table:"
grep -v '^;' tool.tbl
