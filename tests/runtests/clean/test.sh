# clean: -c deletes result, stderr, *.var and *.var.bak below the given dirs and nothing else.
. "$TEST_DIR/../lib.sh"
fixture a 'echo x' x
fixture b/c 'echo x' x
for d in a b/c; do
    touch "$TREE/$d/result" "$TREE/$d/stderr" "$TREE/$d/sim.var" "$TREE/$d/sim.var.bak" "$TREE/$d/keep.txt"
done
touch "$TREE/other.var"
run_runner -c b
echo "-- files after -c b"
(cd "$TREE" && find . -type f | sort)
touch "$TREE/test.sh"
run_runner -c
echo "-- files after -c (default: . as it holds a test.sh)"
(cd "$TREE" && find . -type f | sort)
