#!/bin/bash
# Start-up of the sim mill: status task publishes before anything is commanded, the ini.* and
# iocontrol.0 pins, the tool table for UIs; and nothing left running after the display exits.
. ../lib/run-machine.sh
run_machine
