# lib.sh: start and stop a machine for the Python module tests.
# By default the machine is linuxcncsvr plus nml_responder (a stand-in for task). Set
# OPENEMC_TEST_MACHINE to a command that runs a real configuration in the foreground
# (e.g. "linuxcnc -r") to run the same tests against the real task.
PYTEST_CONFIG="$EMC2_HOME/tests/pylinuxcnc/config/machine.ini"

# start_machine [INI]: start everything and wait until task writes status.
start_machine() {
    local ini="${1:-$PYTEST_CONFIG}"
    if [ -n "${OPENEMC_TEST_MACHINE:-}" ]; then
        $OPENEMC_TEST_MACHINE "$ini" >&2 &
        MACHINE_PID=$!
    else
        SVR_PID=$(linuxcncsvr -ini "$ini" --daemon) || return 1
        "$EMC2_HOME/objects/unit/nml_responder" -ini "$ini" &
        MACHINE_PID=$!
    fi
    python3 - <<'PY' || { stop_machine; return 1; }
import sys, time, linuxcnc
s = linuxcnc.stat()
end = time.time() + 20
while time.time() < end:
    try:
        s.poll()
        if s.taskbeat > 0 and s.linear_units != 0:
            sys.exit(0)
    except linuxcnc.error:
        pass
    time.sleep(0.02)
sys.stderr.write("machine did not start\n")
sys.exit(1)
PY
}

# stop_machine: stop task and the NML master, wait for both.
stop_machine() {
    [ -n "${MACHINE_PID:-}" ] && kill "$MACHINE_PID" 2>/dev/null && wait "$MACHINE_PID" 2>/dev/null
    if [ -n "${SVR_PID:-}" ]; then
        kill "$SVR_PID" 2>/dev/null
        while kill -0 "$SVR_PID" 2>/dev/null; do sleep 0.02; done
    fi
    MACHINE_PID= SVR_PID=
}
