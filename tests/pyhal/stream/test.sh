#!/bin/bash
# stream: Python access to HAL streams, alone and through streamer/sampler.
REALTIME=${REALTIME:-realtime}
$REALTIME start
halcmd -f setup.hal
python3 streams.py
status=$?
halcmd stop
$REALTIME stop
exit $status
