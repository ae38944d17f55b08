#!/bin/bash
# A launcher killed with SIGKILL cannot clean up: its task, NML server, rtapi_app and shared
# memory stay. The next launch in that instance finds the dead launcher in the instance lock,
# stops what it left and starts normally.
export PATH=$PATH:$(cd ../doubles && pwd)
rm -f ./*.out ./*.err
wait_for() {
    for i in $(seq 200); do grep -q "$2" "$1" 2> /dev/null && return 0; sleep 0.05; done
    echo "timeout waiting for '$2' in $1"; cat "$1"; return 1
}
linuxcnc -r test.ini > a.out 2> a.err < /dev/null &
a=$!
wait_for a.err "running headless"
kill -KILL $a; wait $a 2> /dev/null
python3 ../common/leftovers.py > /dev/null && echo "nothing left?" || echo "session left behind"

linuxcnc -r test.ini > b.out 2> b.err < /dev/null &
b=$!
wait_for b.err "running headless"
grep -o "stopping processes left in OPENEMC_INSTANCE=[0-9]* by a linuxcnc that ended" b.err | \
    sed "s/=$OPENEMC_INSTANCE /=<instance> /"
echo "task of the new session: $(halcmd -s show comp | awk '$3 == "inihal" {print $2}')"
kill -TERM $b; wait $b; echo "exit status $?"
python3 ../common/leftovers.py
