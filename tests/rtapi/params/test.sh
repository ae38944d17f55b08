#!/bin/bash
# Module parameters reach the module: every type, arrays, quotes, hex/octal, empty
# strings; an empty number (alone or in an array) is refused; a reload after unload starts again from the compiled-in defaults; the
# component-id counter hands out consecutive ids starting at 1 (hal_lib stand-in).
. ../lib.sh
realtime start
rtapi_app load rtapi_test_params
rtapi_app unload rtapi_test_params
rtapi_app load rtapi_test_params count=0x20 big=-077 'label="a, b"' ints=5,0,6 \
    longs=-1 'names="n1,,n3"'
rtapi_app unload rtapi_test_params
rtapi_app load rtapi_test_params ints=5,,6 2>&1 | sed 's/^.*: //'
rtapi_app load rtapi_test_params count= 2>&1 | sed 's/^.*: //'
rtapi_app load rtapi_test_params label= names= ints=1,2,3,4
rtapi_app list
realtime stop
