#!/bin/bash
# The realtime script: start/status/verify/stop/restart; stop removes this
# instance's HAL, RTAPI and id-counter segments and leaves other instances' alone.
. ../lib.sh
rt_reserve_instance
# mkshm KEY: create a small SysV segment with that key
mkshm() {
    python3 -c 'import ctypes,sys; l=ctypes.CDLL(None); sys.exit(0 if l.shmget(int(sys.argv[1],0),4096,0o1600)>=0 else 1)' "$1"
}
# has KEY: 1 when a segment with KEY exists, else 0
has() { ipcs -m | grep -c "^$1 "; }
realtime status; echo "status -> $?"
RTLIB_DIR=$RTLIB_DIR/missing realtime start; echo "start without hal_lib -> $?"
realtime status; echo "status -> $?"
realtime start; echo "start -> $?"
realtime start; echo "start again -> $?"
realtime status; echo "status -> $?"
# verify: the type name and the exit status agree (0 exactly when realtime)
type=$(realtime verify); rc=$?
case "$type" in
    "No realtime") [ $rc = 1 ] && echo "verify: consistent" ;;
    "Unknown (SCHED_FIFO)"|"Preempt Dynamic"|"Preempt RT") [ $rc = 0 ] && echo "verify: consistent" ;;
    *) echo "verify: unexpected '$type' -> $rc" ;;
esac
for base in 0x48414c32 0x90280a48; do
    mkshm "$(rt_key $base)"
    mkshm "$(rt_key $base $rt_other)"
done
mkshm "$(rt_key 0x48484c34 $rt_other)"
realtime restart; echo "restart -> $?"
echo "ours after restart: HAL $(has "$(rt_key 0x48414c32)") RTAPI $(has "$(rt_key 0x90280a48)")"
realtime stop; echo "stop -> $?"
realtime status; echo "status -> $?"
for base in 0x48414c32 0x90280a48 0x48484c34; do
    echo "$base: ours $(has "$(rt_key $base)") other $(has "$(rt_key $base $rt_other)")"
done
OPENEMC_INSTANCE=$rt_other realtime stop; echo "other stop -> $?"
echo "other left: $(has "$(rt_key 0x48414c32 $rt_other)")"
realtime bogus; echo "bogus -> $?"
# SIGTERM: the master unloads everything, releases its id and exits
realtime start
pid=$(rt_master_pid)
kill -TERM "$pid"
# alive PID: the process exists and is not a zombie
alive() { grep -q '^[^Z]' <(sed -n 's/^State:\s*//p' "/proc/$1/status" 2>/dev/null); }
for ((i = 0; i < 500; i++)); do alive "$pid" || break; sleep 0.02; done
echo "after SIGTERM: process gone $(alive "$pid" && echo no || echo yes), counter $(has "$(rt_key 0x48484c34)")"
realtime status; echo "status -> $?"
# a stopped (unreachable) master: status says so, stop still ends it cleanly
realtime start
pid=$(rt_master_pid)
kill -STOP "$pid"
realtime status 2>/dev/null; echo "status -> $?"
realtime stop 2>/dev/null; echo "stop -> $?"
echo "stopped master gone: $(alive "$pid" && echo no || echo yes)"
realtime status; echo "status -> $?"
