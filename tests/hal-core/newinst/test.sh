#!/bin/bash
# rtapi_app newinst: a registered constructor creates pins for the new instance name;
# unknown components, components without a constructor and duplicates are refused.
err=$(mktemp)
. ../../lib/testmods.sh
trap 'tm_cleanup; rm -f "$err"' EXIT
realtime start 2>"$err" || exit 1
halcmd loadrt hal_test_ctor || exit 1
rtapi_app newinst hal_test_ctor first 42 two three; echo "first: $?"
rtapi_app newinst hal_test_ctor second; echo "second: $?"
halcmd show pin first second | sed -n '3,$p'
rtapi_app newinst hal_test_ctor first 1; echo "duplicate: $?"
rtapi_app newinst no-such-comp x; echo "unknown: $?"
rtapi_app newinst hal-test-plain x; echo "no constructor: $?"
rtapi_app newinst hal_test_ctor; echo "missing name: $?"
halcmd list comp | tr ' ' '\n' | grep -c '^hal_test_ctor$'
halcmd unloadrt hal_test_ctor || exit 1
realtime stop
grep -E '^(HAL|rtapi_app)' "$err"
