# realtime-left: a test that leaves its realtime master running still passes, the runner
# reports and stops the master, and the next test on the same instance finds none.
. "$TEST_DIR/../lib.sh"
fixture a-leaves 'realtime start 2>/dev/null && echo "$OPENEMC_INSTANCE" > "$TEST_DIR/../inst" && echo started' started
fixture b-next 'if rtapi_app ping; then echo "master still there"; else echo "no master"; fi' 'no master'
run_runner -j 1 .
if OPENEMC_INSTANCE=$(cat "$TREE/inst") rtapi_app ping; then echo "master left running"; else echo "no master after the run"; fi
