#!/bin/bash
# rtapi_app error paths: each prints one line naming the module, fails, and leaves
# the master running with everything else still loaded.
. ../lib.sh
# run CMD...: show the exit status and the master's error line (path-normalised)
run() {
    rtapi_app "$@" 2>err.txt
    echo "$* -> $?"
    sed "s|$RTLIB_DIR|RTLIB|g" err.txt
}
realtime start
run load rtapi_test_params fail=1
run load rtapi_test_params fail=22
run load rtapi_test_params count=3
run load rtapi_test_params
run load nosuchmod
run load rtapi_test_params2 count=1
run load ../rtapi_test_params
run load a/b
run load /a..b/
run load rtapi_test_undef
run load rtapi_test_noexit
run load rtapi_test_leak bogus=1
run load rtapi_test_leak nothing
run load rtapi_test_leak label
run load rtapi_test_task period=1ms
run load rtapi_test_task cycles=0x
run load rtapi_test_leak names=a,b,c,d,e
run unload nosuchmod
run unload hal_lib
run debug 6
run debug -1
run debug x
run debug 3
run frobnicate
run newinst
run list
run unload rtapi_test_params
run list
realtime stop
rm -f err.txt
