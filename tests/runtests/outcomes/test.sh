# outcomes: every way a test can end (pass, diff, exit status, checkresult, skip, xfail, xpass, sudo).
. "$TEST_DIR/../lib.sh"
fixture a-pass 'echo hello' hello
fixture b-differs 'echo bye' hello
fixture c-exits 'echo hello; exit 3' hello
fixture d-checkresult-ok 'echo 42'
printf '#!/bin/sh\ngrep -qx 42 "$1"\n' > "$TREE/d-checkresult-ok/checkresult"
fixture e-checkresult-bad 'echo 41'
cp "$TREE/d-checkresult-ok/checkresult" "$TREE/e-checkresult-bad/"
chmod +x "$TREE"/*/checkresult
fixture f-neither 'echo x'
fixture g-skip 'echo x' x
touch "$TREE/g-skip/skip"
fixture h-skip-exec-no 'echo x' x
printf '#!/bin/sh\nexit 1\n' > "$TREE/h-skip-exec-no/skip"
fixture i-skip-exec-yes 'echo x' x
printf '#!/bin/sh\nexit 0\n' > "$TREE/i-skip-exec-yes/skip"
chmod +x "$TREE"/h-*/skip "$TREE"/i-*/skip
fixture j-xfail 'exit 1' x
touch "$TREE/j-xfail/xfail"
fixture k-xpass 'echo x' x
touch "$TREE/k-xpass/xfail"
fixture l-sudo 'echo x' x
printf 'Tests: l-sudo\nRestrictions: sudo\n' > "$TREE/l-sudo/control"
mkdir -p "$TREE/m-executable" "$TREE/n-not-executable"
printf '#!/bin/sh\necho "run as ./test in $(basename "$PWD")"\n' > "$TREE/m-executable/test"
chmod +x "$TREE/m-executable/test"
echo "run as ./test in m-executable" > "$TREE/m-executable/expected"
cp "$TREE/m-executable/test" "$TREE/n-not-executable/test"
chmod -x "$TREE/n-not-executable/test"
run_runner .
echo "-- files left"
(cd "$TREE" && find . -name result -o -name stderr | sort)
echo "-- with -u"
run_runner -u .
