# lib.sh: helpers for the inifile tests.
set -e

# q ARGS...: run inivar; print its output (stderr first, as it comes before the value) and exit status
q() {
    local rc=0
    inivar "$@" 2>&1 || rc=$?
    echo "[exit $rc]"
}
