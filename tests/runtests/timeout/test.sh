# timeout: -t kills the whole process group of a test that runs too long and fails it.
. "$TEST_DIR/../lib.sh"
fixture a-slow 'sleep 30 & echo $! > "$TEST_DIR/bgpid"; sleep 30; echo done' done
fixture b-fast 'echo quick' quick
run_runner -t 2 .
pid=$(cat "$TREE/a-slow/bgpid")
# killed means gone or a zombie waiting for its new parent to reap it
state=$(awk '{ print $3 }' "/proc/$pid/stat" 2> /dev/null || true)
case "$state" in ""|Z) echo "background sleep killed" ;; *) echo "background sleep survived ($state)" ;; esac
