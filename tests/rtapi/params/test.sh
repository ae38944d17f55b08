#!/bin/bash
# Module parameters reach the module: every type, arrays, quotes, hex/octal, empty
# values; a reload after unload starts again from the compiled-in defaults; the
# component-id counter hands out consecutive ids starting at 1 (hal_lib stand-in).
. ../lib.sh
realtime start
rtapi_app load rtapi_test_params
rtapi_app unload rtapi_test_params
rtapi_app load rtapi_test_params count=0x20 big=-077 'label="a, b"' ints=5,,6 \
    longs=-1 'names="n1,,n3"'
rtapi_app unload rtapi_test_params
rtapi_app load rtapi_test_params count= label= names= ints=1,2,3,4
rtapi_app list
realtime stop
