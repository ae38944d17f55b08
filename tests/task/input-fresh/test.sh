#!/bin/bash
# M66 with a slow servo thread: the value read is the one set just before (see test-ui.py).
. ../lib/run-machine.sh
run_machine
