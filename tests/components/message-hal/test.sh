#!/bin/bash
# message in real HAL: quoted messages with spaces are printed on the right edges (stderr of the
# realtime side, collected after halrun ends so the order is fixed); too few messages fail the load.
err=$(mktemp)
trap 'rm -f "$err" "$err.hal"' EXIT
halrun -f message.hal 2>"$err"
echo "rc=$?"
grep -E '^(Slideway oil low|Door open)$' "$err"
echo 'loadrt message count=3 messages="one,two"' > "$err.hal"
halrun -f "$err.hal" 2>"$err"
echo "rc=$?"
grep -o 'MESSAGE: ERROR.*' "$err"
