#!/bin/bash
# Feed hold while task has more moves than the planner can hold (see test-ui.py).
. ../lib/run-machine.sh
run_machine
