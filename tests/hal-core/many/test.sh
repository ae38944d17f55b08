#!/bin/bash
# More than 64 rtapi ids and tasks in rtapi_app: 200 components from one module,
# then 75 threads (each a task plus an id for its __<thread> pseudo component).
. ../../lib/testmods.sh
trap tm_cleanup EXIT
realtime start 2>/dev/null || exit 1
halcmd loadrt hal_test_many count=200 || exit 1
echo "components: $(halcmd list comp | tr ' ' '\n' | grep -c '^hal_test_many\.')"
halcmd getp hal_test_many.199.out
set +x
for i in $(seq 1 25); do
    halcmd loadrt threads name1=t${i}a period1=50000000 name2=t${i}b period2=50000000 \
        name3=t${i}c period3=50000000 || { echo "threads load $i failed"; break; }
    [ $i = 25 ] || halcmd unloadrt threads
done
set -x
echo "threads: $(halcmd list thread | tr ' ' '\n' | grep -c '^t[0-9]*[abc]$')"
halcmd getp t25c.tmax
halcmd unloadrt threads || exit 1
halcmd unloadrt hal_test_many || exit 1
echo "left: $(halcmd list comp | tr ' ' '\n' | grep -c '^hal_test_many')"
realtime stop
