# overrun: a test.hal whose result holds a line 'overrun' is run again, at most 10 times in all.
. "$TEST_DIR/../lib.sh"
# a stand-in halrun that reports an overrun until the run count reaches the number in ./clean-after
mkdir -p "$WORK/fakebin"
cat > "$WORK/fakebin/halrun" <<'HALRUN'
#!/bin/sh
n=$(( $(cat runs 2> /dev/null || echo 0) + 1 ))
echo $n > runs
echo "sample $n"
if [ "$n" -lt "$(cat clean-after)" ]; then echo overrun; fi
HALRUN
chmod +x "$WORK/fakebin/halrun"
export PATH="$WORK/fakebin:$EMC2_HOME/bin:$EMC2_HOME/scripts:$PATH"
mkdir -p "$TREE/a-third-run" "$TREE/b-never"
for d in a-third-run b-never; do echo "loadrt nothing" > "$TREE/$d/test.hal"; done
echo 3 > "$TREE/a-third-run/clean-after"
echo "sample 3" > "$TREE/a-third-run/expected"
echo 99 > "$TREE/b-never/clean-after"
echo "sample 10" > "$TREE/b-never/expected"
run_runner .
echo "-- runs: $(cat "$TREE/a-third-run/runs") $(cat "$TREE/b-never/runs")"
