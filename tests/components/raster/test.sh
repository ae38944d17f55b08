#!/bin/bash
# raster: programs written into a real HAL port, passes traced cycle by cycle with streamer/sampler.
"${REALTIME:-realtime}" start
python3 raster_test.py
status=$?
halcmd stop
halcmd unload all
"${REALTIME:-realtime}" stop
exit $status
