# parallel: -j 2 runs two tests at once, each with its own OPENEMC_INSTANCE.
. "$TEST_DIR/../lib.sh"
# each test records its instance, then waits (bounded) for the other one's marker
waiter='echo "$OPENEMC_INSTANCE" > ../$ME.instance
for i in $(seq 600); do [ -e ../$OTHER.instance ] && break; sleep 0.1; done
test -e ../$OTHER.instance && echo met'
fixture a "ME=a OTHER=b; $waiter" met
fixture b "ME=b OTHER=a; $waiter" met
run_runner -j 2 -t 120 . | sort
a=$(cat "$TREE/a.instance") b=$(cat "$TREE/b.instance")
if [ "$a" != "$b" ]; then echo "instances differ"; else echo "same instance $a"; fi
case "$a$b" in *[!0-9]*|"") echo "bad instance '$a' '$b'" ;; esac
