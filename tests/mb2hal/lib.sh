# lib.sh: sourced by the mb2hal tests: modbus-sim start/stop, bounded pin polling, cleanup on exit.
MB_TMP=$(mktemp -d)
SIM_PID=
SIM_PORT=0
SIM_PTY=
SIM_N=0

# Stops the simulator and any mb2hal left, then removes the temp dir (EXIT trap).
mb_cleanup() {
    halcmd unloadusr all > /dev/null 2>&1
    sim_stop
    realtime stop > /dev/null 2>&1
    rm -rf "$MB_TMP"
}
trap mb_cleanup EXIT

# sim_start ARGS...: starts modbus-sim on $SIM_PORT (0 = any) with a command FIFO on fd 3;
# sets SIM_PORT (TCP) or SIM_PTY (with --rtu).
sim_start() {
    SIM_N=$((SIM_N + 1))
    local fifo="$MB_TMP/sim$SIM_N.in" out="$MB_TMP/sim$SIM_N.port" n=0
    mkfifo "$fifo"
    modbus-sim --port "$SIM_PORT" "$@" < "$fifo" > "$out" 2>> "$MB_TMP/sim.err" &
    SIM_PID=$!
    exec 3> "$fifo"
    until grep -q '^p[ot][rty]* ' "$out"; do
        n=$((n + 1))
        if [ $n -gt 1000 ] || ! kill -0 $SIM_PID 2> /dev/null; then
            echo "modbus-sim did not start"; cat "$MB_TMP/sim.err"; exit 1
        fi
        sleep 0.01
    done
    SIM_PORT=$(awk '/^port /{print $2}' "$out")
    SIM_PTY=$(awk '/^pty /{print $2}' "$out")
}

# sim_stop: ends the simulator (its port stays in SIM_PORT for a restart).
sim_stop() {
    [ -n "$SIM_PID" ] || return 0
    exec 3>&-
    kill $SIM_PID 2> /dev/null
    wait $SIM_PID 2> /dev/null
    SIM_PID=
}

# sim_set TABLE ADDR VALUE: changes a value inside the running simulator.
sim_set() {
    echo "set $1 $2 $3" >&3
}

# wait_until DESCRIPTION COMMAND...: polls COMMAND until it succeeds (at most ~20 s); prints the outcome.
wait_until() {
    local what=$1 n=0
    shift
    until "$@"; do
        n=$((n + 1))
        if [ $n -gt 2000 ]; then echo "timed out: $what"; return 1; fi
        sleep 0.01
    done
    echo "ok: $what"
}

# pin_is PIN VALUE: succeeds when halcmd getp PIN prints VALUE.
pin_is() {
    [ "$(halcmd getp "$1" 2> /dev/null)" = "$2" ]
}

# pin_above PIN N: succeeds when the integer pin PIN is greater than N.
pin_above() {
    local v
    v=$(halcmd getp "$1" 2> /dev/null) || return 1
    [ $((v)) -gt "$2" ]
}

# logged LINE: succeeds when the simulator's write log holds LINE.
logged() {
    grep -qx "$1" "$MB_TMP/writes.log" 2> /dev/null
}

# tcp_link [ID]: the link keys of a transaction talking to the simulator.
tcp_link() {
    printf 'LINK_TYPE=tcp\nTCP_IP=127.0.0.1\nTCP_PORT=%s\nMB_SLAVE_ID=%s\n' "$SIM_PORT" "${1:-1}"
}
