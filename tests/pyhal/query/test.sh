#!/bin/bash
# query: hal.query dictionaries for a small HAL configuration.
REALTIME=${REALTIME:-realtime}
$REALTIME start
halcmd -f setup.hal
python3 query.py
status=$?
$REALTIME stop
exit $status
