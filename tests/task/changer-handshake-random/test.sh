#!/bin/bash
# Random tool changer with a hand-answered handshake (see test-ui.py).
. ../lib/run-machine.sh
run_machine
