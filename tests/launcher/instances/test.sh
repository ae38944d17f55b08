#!/bin/bash
# Two configurations side by side: without OPENEMC_INSTANCE each launch takes the first free
# instance and says which; with the same OPENEMC_INSTANCE the second launch is refused. SIGTERM
# and SIGINT stop a session completely (a task that ignores SIGTERM is killed); nothing is
# left in either instance.
export PATH=$PATH:$(cd ../doubles && pwd)
rm -f ./*.out ./*.err

# wait_for FILE TEXT: until FILE contains TEXT (at most 10 s)
wait_for() {
    for i in $(seq 200); do grep -q "$2" "$1" 2> /dev/null && return 0; sleep 0.05; done
    echo "timeout waiting for '$2' in $1"; cat "$1"; return 1
}
# instance_of FILE: the instance a launch reported
instance_of() { sed -n 's/.*running in OPENEMC_INSTANCE=\([0-9]*\).*/\1/p' "$1"; }

mine=$OPENEMC_INSTANCE
unset OPENEMC_INSTANCE
linuxcnc -r test.ini > a.out 2> a.err < /dev/null &
a=$!
wait_for a.err "running headless"
linuxcnc -r test.ini > b.out 2> b.err < /dev/null &
b=$!
wait_for b.err "running headless"
ia=$(instance_of a.err); ib=$(instance_of b.err)
[ -n "$ia" ] && [ -n "$ib" ] && [ "$ia" != "$ib" ] && echo "two launches, two instances"
echo "A: s.gain=$(OPENEMC_INSTANCE=$ia halcmd getp s.gain)"
echo "B: s.gain=$(OPENEMC_INSTANCE=$ib halcmd getp s.gain)"

OPENEMC_INSTANCE=$ia linuxcnc -r test.ini > c.out 2> c.err < /dev/null
echo "same instance again: exit status $?"
sed -e "s/=$ia /=<A> /" -e "s|([0-9]* $PWD/|(<pid> |" c.err

kill -TERM $a; wait $a; echo "A after SIGTERM: exit status $?"
kill -INT $b; wait $b; echo "B after SIGINT: exit status $?"
python3 ../common/leftovers.py $ia $ib

export OPENEMC_INSTANCE=$mine
linuxcnc -r stubborn.ini > d.out 2> d.err < /dev/null &
d=$!
wait_for d.err "running headless"
kill -TERM $d; wait $d; echo "task ignoring SIGTERM: exit status $?"
grep -o "did not stop on SIGTERM" d.err
python3 ../common/leftovers.py
