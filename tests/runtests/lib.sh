# lib.sh: helpers for the runtests tests: build fixture test trees in a temp dir and run the runner on them.
set -e
set +x  # keep the trace of these helpers out of the captured runner output
WORK=$(mktemp -d)
TREE=$WORK/tree
mkdir -p "$TREE"
trap 'rm -rf "$WORK"' EXIT
RUNNER=$EMC2_HOME/scripts/runtests

# fixture DIR SCRIPT [EXPECTED]: a test.sh test whose stdout is compared with EXPECTED (if given)
fixture() {
    mkdir -p "$TREE/$1"
    printf '%s\n' "$2" > "$TREE/$1/test.sh"
    if [ $# -ge 3 ]; then printf '%s\n' "$3" > "$TREE/$1/expected"; fi
}

# mask: hide the timestamps of diff headers and the instance numbers, which vary from run to run
mask() {
    sed -e 's/^\(---\|+++\) \([^\t]*\)\t.*/\1 \2/' -e 's/instance=[0-9]*/instance=N/g'
}

# run_runner ARGS...: run the runner in the fixture tree; print its stdout, stderr and exit status
run_runner() {
    local rc=0
    (cd "$TREE" && "$RUNNER" "$@") > "$WORK/out" 2> "$WORK/err" || rc=$?
    mask < "$WORK/out"
    echo "-- stderr"
    mask < "$WORK/err"
    echo "-- exit $rc"
}
