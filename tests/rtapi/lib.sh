# lib.sh: sourced by tests/rtapi/*/test.sh. Sets up a private RTLIB_DIR where the
# RTAPI test modules (built into objects/testlib/) live and rtapi_test_hal stands in
# for hal_lib, so these tests exercise rtapi_app alone. Call rt_cleanup at the end (also run on exit).

rt_top=${EMC2_HOME:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
export PATH=$rt_top/bin:$PATH
rt_lib=$(mktemp -d /tmp/rtapi-test.XXXXXX)
for rt_mod in params noexit undef leak task; do
    ln -s "$rt_top/objects/testlib/rtapi_test_$rt_mod.so" "$rt_lib/rtapi_test_$rt_mod.so"
done
ln -s "$rt_top/objects/testlib/rtapi_test_hal.so" "$rt_lib/hal_lib.so"
export RTLIB_DIR=$rt_lib
# runtests gives this test its instance exclusively: a master answering on it is
# debris of an earlier run, which would serve the wrong RTLIB_DIR
realtime stop >/dev/null 2>&1

# rt_key BASE [INSTANCE]: SysV key of BASE for an instance (default: ours)
rt_key() {
    printf '0x%08x' $(( $1 ^ (${2:-${OPENEMC_INSTANCE:-0}} << 24) ))
}

# rt_open_lock N: open the lock file of instance N read-only as fd rt_other_fd, in the
# directory shared by all users or else in this user's own one (as scripts/runtests_pool.py)
rt_open_lock() {
    local d m base=${TMPDIR:-/tmp}/openemc-instance-locks
    for d in "$base:1777" "$base-$(id -u):700"; do
        m=${d##*:} d=${d%:*}
        [ -e "$d/$1.lock" ] || (umask 0; mkdir -p -m "$m" "$d" && : >> "$d/$1.lock") 2>/dev/null
        if [ -r "$d/$1.lock" ] && exec {rt_other_fd}< "$d/$1.lock"; then
            return 0
        fi
    done
    return 1
}

# rt_reserve_instance: set rt_other to a free instance, locked like runtests does
rt_reserve_instance() {
    local i
    for i in $(seq 255 -1 1); do
        ipcs -m | grep -qi "$(rt_key 0x48414C32 "$i")" && continue
        rt_open_lock "$i" || continue
        if flock -n "$rt_other_fd"; then
            rt_other=$i
            OPENEMC_INSTANCE=$i realtime stop >/dev/null 2>&1
            return 0
        fi
        exec {rt_other_fd}<&-
    done
    echo "no free instance" >&2
    return 1
}

# rt_master_pid: pid of the rtapi_app master serving our instance (empty if none)
rt_master_pid() {
    local p
    for p in $(pgrep -x rtapi_app); do
        if grep -qx "OPENEMC_INSTANCE=$OPENEMC_INSTANCE" \
            <( (tr '\0' '\n' < "/proc/$p/environ") 2>/dev/null) &&
            grep -q '^[^Z]' <(sed -n 's/^State:\s*//p' "/proc/$p/status" 2>/dev/null); then
            echo "$p"
            return 0
        fi
    done
}

# rt_cleanup: stop every master this test started and remove the private rtlib
rt_cleanup() {
    realtime stop >/dev/null 2>&1
    if [ -n "${rt_other:-}" ]; then
        OPENEMC_INSTANCE=$rt_other realtime stop >/dev/null 2>&1
    fi
    rm -rf "$rt_lib"
}
trap rt_cleanup EXIT
