#!/bin/bash
# realtime: start, stop, restart, query or verify this instance's rtapi_app master.
# The instance is $OPENEMC_INSTANCE (default 0); stop removes only its shm keys.

here=$(cd "$(dirname "$0")" && pwd)
if [ -x "$here/rtapi_app" ]; then RTAPI_APP=$here/rtapi_app; else RTAPI_APP=rtapi_app; fi
case "${1:-}" in
    --help|-h)
        echo "Usage: realtime {start|load|stop|unload|restart|status|verify}"
        echo "Starts, stops or checks the rtapi_app master of instance \$OPENEMC_INSTANCE (0..16777215,"
        echo "default 0); stop also removes that instance's shared memory. verify prints the"
        echo "kind of realtime this machine offers and exits 0 only when it is realtime."
        exit 0 ;;
esac
instance=${OPENEMC_INSTANCE:-0}
# a decimal 0..16777215 (at most 8 digits), as rtapi_instance() accepts; anything else would
# share another session
case "$instance" in
    ''|*[!0-9]*) instance=-1 ;;
    *) if [ ${#instance} -le 8 ]; then instance=$((10#$instance)); else instance=-1; fi ;;
esac
if [ "$instance" -lt 0 ] || [ "$instance" -gt 16777215 ]; then
    echo "realtime: OPENEMC_INSTANCE='$OPENEMC_INSTANCE' is not an instance number 0..16777215" >&2
    exit 1
fi

# instance_key BASE: the SysV key this instance uses for a LinuxCNC base key
instance_key() {
    if [ "$instance" -le 255 ]; then
        printf '0x%08x' $(( $1 ^ (instance << 24) ))
    else
        printf '0x%08x' $(( ($1 ^ (instance << 8 | 0xA5)) & 0xFFFFFFFF ))
    fi
}

# remove_shm: drop the HAL, RTAPI and id-counter segments of this instance
remove_shm() {
    local base
    for base in 0x48414c32 0x90280a48 0x48484c34; do
        ipcrm -M "$(instance_key $base)" 2>/dev/null
    done
    return 0
}

# master_pids: pids of live rtapi_app processes of this instance
master_pids() {
    local pid env state
    for pid in $(pgrep -x rtapi_app); do
        state=$(sed -n 's/^State:[[:space:]]*\(.\).*/\1/p' "/proc/$pid/status" 2>/dev/null)
        [ -n "$state" ] && [ "$state" != Z ] || continue
        env=$( (tr "\\0" "\\n" < "/proc/$pid/environ") 2>/dev/null | sed -n "s/^OPENEMC_INSTANCE=//p")
        case "$env" in
            '') env=0 ;;
            [0-9]|[0-9][0-9]|[0-9][0-9][0-9]) env=$((10#$env)) ;;
            *) continue ;;
        esac
        [ "$env" = "$instance" ] && echo "$pid"
    done
}

# master_process_exists: some rtapi_app of this instance still lives
master_process_exists() {
    [ -n "$(master_pids)" ]
}

# kill_unreachable: a master that no longer answers gets SIGTERM, then SIGKILL
kill_unreachable() {
    local pids i
    pids=$(master_pids)
    [ -n "$pids" ] || return 0
    kill -TERM $pids 2>/dev/null
    kill -CONT $pids 2>/dev/null
    for ((i = 0; i < 50; i++)); do
        [ -n "$(master_pids)" ] || return 0
        sleep 0.1
    done
    echo "ERROR: rtapi_app failed to die" >&2
    kill -KILL $(master_pids) 2>/dev/null
    return 1
}

# do_stop: ask the master to exit (rtapi_app waits <= 5 s for it), stop an
# unreachable one, then remove this instance's shm
do_stop() {
    local rc=0
    if "$RTAPI_APP" ping; then
        "$RTAPI_APP" exit || rc=1
    fi
    kill_unreachable || rc=1
    remove_shm
    return $rc
}

# do_status: report whether the master runs and answers
do_status() {
    if "$RTAPI_APP" ping; then
        echo "rtapi_app is running"
        return 0
    fi
    if master_process_exists; then
        echo "rtapi_app is running but not reachable"
    else
        echo "rtapi_app is not running"
    fi
    return 1
}

case "$1" in
    start|load) exec "$RTAPI_APP" start ;;
    stop|unload) do_stop ;;
    restart) do_stop; exec "$RTAPI_APP" start ;;
    status) do_status ;;
    verify) exec "$RTAPI_APP" check_rt ;;
    *) echo "Usage: $0 {start|load|stop|unload|restart|status|verify}" >&2; exit 1 ;;
esac
