# lib.sh: a machine (linuxcncsvr + nml_responder, the stand-in for task) and linuxcncrsh
# on a port of this test's instance (21000 + OPENEMC_INSTANCE), for the linuxcncrsh tests.
RSH_INI="$EMC2_HOME/tests/linuxcncrsh/common/rsh.ini"
RSH_PORT=$((21000 + ${OPENEMC_INSTANCE:-0}))
export RSH_PORT

# start_machine: the NML master and the responder; wait until it publishes status.
start_machine() {
    SVR_PID=$(linuxcncsvr -ini "$RSH_INI" --daemon) || return 1
    "$EMC2_HOME/objects/unit/nml_responder" -ini "$RSH_INI" &
    MACHINE_PID=$!
    python3 "$EMC2_HOME/tests/linuxcncrsh/common/rshclient.py" wait-status || { stop_machine; return 1; }
}

# start_rsh [OPTIONS]: linuxcncrsh in the background; wait until it accepts connections.
start_rsh() {
    linuxcncrsh -p "$RSH_PORT" "$@" -- -ini "$RSH_INI" > rsh.log 2>&1 &
    RSH_PID=$!
    python3 "$EMC2_HOME/tests/linuxcncrsh/common/rshclient.py" wait-port "$RSH_PORT" || return 1
}

# stop_rsh: SIGTERM linuxcncrsh (if still running) and print its exit status.
stop_rsh() {
    [ -n "${RSH_PID:-}" ] || return 0
    kill "$RSH_PID" 2>/dev/null
    wait "$RSH_PID"
    echo "linuxcncrsh exit $?"
    RSH_PID=
}

# stop_machine: the responder and the NML master.
stop_machine() {
    [ -n "${MACHINE_PID:-}" ] && kill "$MACHINE_PID" 2>/dev/null && wait "$MACHINE_PID" 2>/dev/null
    if [ -n "${SVR_PID:-}" ]; then
        kill "$SVR_PID" 2>/dev/null
        while kill -0 "$SVR_PID" 2>/dev/null; do sleep 0.02; done
    fi
    MACHINE_PID= SVR_PID=
}
