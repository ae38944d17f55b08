# lib.sh: helpers for the inifile tests.
set -e

# with_status CMD ARGS...: run CMD; print its output (stderr and stdout as they come), then its exit status
with_status() {
    local rc=0
    "$@" 2>&1 || rc=$?
    echo "[exit $rc]"
}

# q ARGS...: inivar with its output and exit status
q() { with_status inivar "$@"; }

# vars FILE KEY...: q for each KEY of FILE (first value, any section)
vars() {
    local file=$1 key
    shift
    for key in "$@"; do q -ini "$file" -var "$key"; done
}
