#!/bin/bash
# component-link: Python hal component <-> halcmd, values both ways.
REALTIME=${REALTIME:-realtime}
$REALTIME start
python3 pycomp.py
status=$?
$REALTIME stop
exit $status
