#!/bin/bash
# Load and unload a module using an id, shm, a task and string parameters 1000
# times: no leaked shared memory segments, file descriptors or memory. Memory is
# judged by the master's RSS growth, or on an ASan build (whose quarantine holds
# freed memory) by the LeakSanitizer check the master runs when it exits.
. ../lib.sh
asan=$(sed -n 's/^ASAN_FLAGS *= *\(-fsanitize\)/\1/p' "$rt_top/Makefile.inc")
realtime start 2> "$rt_lib/master.err"
pid=$(rt_master_pid)
# cycle N: load/unload the leak module N times, stopping at the first failure
cycle() {
    local i
    for ((i = 0; i < $1; i++)); do
        rtapi_app load rtapi_test_leak label=run$i names=a,b,c || return 1
        rtapi_app unload rtapi_test_leak || return 1
    done
}
# snapshot: SysV segments mapped, open fds and VmRSS (kB) of the master
snapshot() {
    shm=$(grep -c SYSV /proc/$pid/maps)
    fds=$(ls /proc/$pid/fd | wc -l)
    rss=$(awk '/^VmRSS/ {print $2}' /proc/$pid/status)
}
set +x
cycle 50 && echo "warm-up: ok"
snapshot; shm0=$shm fds0=$fds rss0=$rss
cycle 950 && echo "950 more cycles: ok"
snapshot
set -x
echo "shm segments mapped: $([ "$shm" -eq "$shm0" ] && echo same || echo "grew $shm0 -> $shm")"
echo "fds: $([ "$fds" -eq "$fds0" ] && echo same || echo "changed $fds0 -> $fds")"
if [ -z "$asan" ]; then
    memory=$([ $((rss - rss0)) -lt 1024 ] && echo "no leak" || echo "RSS grew $rss0 -> $rss kB")
fi
echo "leak module key gone: $(ipcs -m | grep -c "$(rt_key 0x524c4b31)")"
realtime stop
cat "$rt_lib/master.err" >&2
if [ -n "$asan" ]; then
    memory=$(grep -q Sanitizer "$rt_lib/master.err" && echo "sanitizer report" || echo "no leak")
fi
echo "memory: $memory"
