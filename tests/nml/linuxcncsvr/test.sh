#!/bin/bash
# linuxcncsvr: creates exactly the buffers of [EMC]NML_FILE plus the tool data, is ready
# when --daemon returns or the ready file appears, refuses a second master and foreign
# segments, and removes only what it created on SIGTERM and SIGINT.
cd "$(dirname "$0")"
exists() { for k in 3001 3002 3003 0x00544F4C "$@"; do ./shm.py exists $k | sed 's/^0x..//'; done; }

echo "== keys follow the instance"
a=$(OPENEMC_INSTANCE=7 linuxcncsvr -ini test.ini --list | awk '$1=="cmd"{print $2}')
b=$(OPENEMC_INSTANCE=8 linuxcncsvr -ini test.ini --list | awk '$1=="cmd"{print $2}')
echo "instance 7: $a, instance 8: $b"

echo "== daemon"
./shm.py create 3004
pid=$(linuxcncsvr -ini test.ini --daemon)
echo "daemon exit $?"
exists 3004
linuxcncsvr -ini test.ini 2>&1 | sed 's/pid [0-9]*/pid N/; s/0x[0-9a-f]\{8\}/KEY/'
echo "second master exit ${PIPESTATUS[0]}"
kill -TERM "$pid"
while kill -0 "$pid" 2>/dev/null; do sleep 0.05; done
echo "after SIGTERM:"
exists 3004

echo "== ready file and SIGINT"
rm -f ready
linuxcncsvr -ini test.ini --ready-file ready &
pid=$!
for i in $(seq 200); do [ -f ready ] && break; sleep 0.05; done
[ "$(cat ready)" = "$pid" ] && echo "ready file holds the pid"
exists
kill -INT "$pid"
wait "$pid"
echo "exit $?"
[ -f ready ] || echo "ready file removed"
exists

echo "== a foreign segment on one of its keys"
./shm.py create 3002
linuxcncsvr -ini test.ini --daemon 2>&1 | sed 's/0x[0-9a-f]\{8\}/KEY/'
echo "exit ${PIPESTATUS[0]}"
exists
./shm.py remove 3002
./shm.py remove 3004
