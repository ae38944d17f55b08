#!/bin/bash
# ports: byte FIFOs between PORT pins of a Python component.
REALTIME=${REALTIME:-realtime}
$REALTIME start
python3 ports.py
status=$?
$REALTIME stop
exit $status
