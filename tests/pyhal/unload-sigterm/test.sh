#!/bin/bash
# unload-sigterm: halcmd unload of a Python component raises KeyboardInterrupt.
REALTIME=${REALTIME:-realtime}
$REALTIME start
halcmd loadusr -Wn pywait python3 waiter.py
halcmd net level pywait.level
halcmd setp pywait.gain 4
echo "ready: $(halcmd getp pywait.level)"
halcmd unload pywait
halcmd waitusr pywait
echo "left: [$(halcmd list comp pywait)] level=$(halcmd gets level)"
$REALTIME stop
