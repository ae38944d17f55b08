# lib.sh: sourced by the pyhal tests: runs a Python script on a started HAL with the shared helper importable.
# pyhal_run SCRIPT [SETUP.hal]: start realtime, load SETUP, run SCRIPT, stop; exits with SCRIPT's status.
pyhal_run() {
    local realtime=${REALTIME:-realtime} status
    $realtime start
    [ -n "$2" ] && halcmd -f "$2"
    PYTHONPATH="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)${PYTHONPATH:+:$PYTHONPATH}" python3 "$1"
    status=$?
    [ -n "$2" ] && halcmd stop
    $realtime stop
    exit $status
}
