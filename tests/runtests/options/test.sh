# options: -n keeps files of passing tests, -p prints output of failures, -s stops early, -h and bad options.
. "$TEST_DIR/../lib.sh"
fixture a-pass 'echo hello' hello
fixture b-fail 'echo one; echo two >&2; exit 2' x
fixture c-fail 'echo x' y
fixture d-pass 'echo x' x
echo "== -n -s"
run_runner -n -s .
echo "-- files left"
(cd "$TREE" && find . -name result -o -name stderr | sort)
echo "== -p on b-fail"
run_runner -p b-fail
echo "== -v shows the test's output"
run_runner -v a-pass
echo "== -h"
run_runner -h | head -2
echo "== -q (unknown option)"
run_runner -q | sed -n '1p;/^-- /p'
echo "== -j 0"
run_runner -j 0 .
echo "== -c does not run tests"
run_runner -c .
