#!/bin/bash
# Programs in AUTO: run, pause/resume, optional stop, step, abort, run from a line, a G-code error (program stops, machine stays on).
. ../lib/run-machine.sh
run_machine
