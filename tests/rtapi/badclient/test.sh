#!/bin/bash
# Clients that die mid-request, send bad length fields or stall half-way do not
# break rtapi_app: it drops them (10 s receive timeout) and keeps serving with
# everything still loaded.
. ../lib.sh
realtime start
rtapi_app load rtapi_test_params count=4
python3 ./client.py
echo "ping: $(rtapi_app ping && echo ok)"
rtapi_app list
# a client that stalls half-way is dropped after the master's receive timeout
python3 ./client.py hold held.flag &
holder=$!
for ((i = 0; i < 500; i++)); do [ -e held.flag ] && break; sleep 0.02; done
echo "list while a client stalls:"
rtapi_app list
kill $holder
wait $holder 2>/dev/null
rm -f held.flag
rtapi_app unload rtapi_test_params && echo "unload: ok"
realtime stop
