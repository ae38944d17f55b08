#!/bin/bash
# E-stop, machine on, refusals, homing, MDI before/while/after homing, the MDI queue, jogs, overrides, coolant, spindle.
. ../lib/run-machine.sh
run_machine
