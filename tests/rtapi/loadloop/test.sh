#!/bin/bash
# Load and unload a module using an id, shm, a task and string parameters 1000
# times: no leaked shared memory segments, file descriptors or memory.
. ../lib.sh
realtime start
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
echo "rss growth under 1 MiB: $([ $((rss - rss0)) -lt 1024 ] && echo yes || echo "no ($rss0 -> $rss kB)")"
echo "leak module key gone: $(ipcs -m | grep -c "$(rt_key 0x524c4b31)")"
realtime stop
