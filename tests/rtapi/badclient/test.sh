#!/bin/bash
# Clients that die mid-request or send bad length fields do not break rtapi_app:
# it drops them and keeps serving with everything still loaded.
. ../lib.sh
realtime start
rtapi_app load rtapi_test_params count=4
python3 ./client.py
echo "ping: $(rtapi_app ping && echo ok)"
rtapi_app list
rtapi_app unload rtapi_test_params && echo "unload: ok"
realtime stop
