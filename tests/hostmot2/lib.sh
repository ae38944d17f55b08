# lib.sh: sourced by the hostmot2 tests: mesa-sim start/stop and queries, bounded polling, cleanup.
HM2_TMP=$(mktemp -d)
SIM_PID=
SIM_N=0
INST=${OPENEMC_INSTANCE:-211}
# A loopback address of our own per instance, so parallel tests never share a card.
SIM_IP=127.$((20 + INST / 250)).$((INST % 250)).1
BOARD=hm2_7i92.0

# Stops HAL and the simulator, removes the temp dir (EXIT trap).
hm2_cleanup() {
    [ -f "$RT_LOG" ] && { echo "---- driver log (tail)"; tail -n 40 "$RT_LOG"; } >&2
    [ -f "$HM2_TMP/sim.err" ] && { echo "---- sim stderr"; cat "$HM2_TMP/sim.err"; } >&2
    halcmd stop > /dev/null 2>&1
    halcmd unload all > /dev/null 2>&1
    sim_stop
    realtime stop > /dev/null 2>&1
    rm -rf "$HM2_TMP"
}
trap hm2_cleanup EXIT

# sim_start ARGS...: runs mesa-sim on $SIM_IP with commands on fd 3 and its lines in $SIM_OUT.
sim_start() {
    SIM_N=$((SIM_N + 1))
    local fifo="$HM2_TMP/sim$SIM_N.in" n=0
    SIM_OUT="$HM2_TMP/sim$SIM_N.out"
    mkfifo "$fifo"
    mesa-sim --ip "$SIM_IP" "$@" < "$fifo" > "$SIM_OUT" 2>> "$HM2_TMP/sim.err" &
    SIM_PID=$!
    exec 3> "$fifo"
    until grep -q '^ready ' "$SIM_OUT"; do
        n=$((n + 1))
        if [ $n -gt 1000 ] || ! kill -0 $SIM_PID 2> /dev/null; then
            echo "mesa-sim did not start"; cat "$HM2_TMP/sim.err"; exit 1
        fi
        sleep 0.01
    done
}

# sim_stop: ends the simulator.
sim_stop() {
    [ -n "$SIM_PID" ] || return 0
    echo quit >&3 2> /dev/null
    exec 3>&-
    wait $SIM_PID 2> /dev/null
    SIM_PID=
}

# sim CMD...: sends a command and prints the simulator's answer line.
sim() {
    local before n=0
    before=$(wc -l < "$SIM_OUT")
    echo "$*" >&3
    until [ "$(wc -l < "$SIM_OUT")" -gt "$before" ]; do
        n=$((n + 1))
        if [ $n -gt 500 ]; then echo "sim: no answer to '$*'"; return 1; fi
        sleep 0.01
    done
    tail -n +"$((before + 1))" "$SIM_OUT" | grep -v '^bite$\|^watchdog cleared$' | head -n 1
}

# sim_field CMD... FIELD: one named field of a sim answer ("get stepgen 0" "emitted").
sim_field() {
    local field=${*: -1}
    sim "${@:1:$#-1}" | awk -v f="$field" '{ for (i = 1; i < NF; i++) if ($i == f) print $(i + 1) }'
}

# sim_is FIELD VALUE CMD...: the simulator's answer to CMD has FIELD equal to VALUE.
sim_is() {
    local field=$1 value=$2
    shift 2
    [ "$(sim_field "$@" "$field")" = "$value" ]
}

# sim_answer_is LINE CMD...: the simulator answers CMD with exactly LINE.
sim_answer_is() {
    local line=$1
    shift
    [ "$(sim "$@")" = "$line" ]
}

# sim_said LINE: the simulator printed exactly LINE.
sim_said() {
    grep -qx "$1" "$SIM_OUT"
}

# rt_start: the realtime master, its messages (the drivers' log lines) in $RT_LOG.
RT_LOG="$HM2_TMP/rtapi.log"
rt_start() {
    realtime start > "$RT_LOG" 2>&1 || { echo "realtime start failed"; cat "$RT_LOG"; exit 1; }
}

# rt_log_has TEXT: the drivers printed a line containing TEXT (fixed string).
rt_log_has() {
    grep -qF -- "$1" "$RT_LOG"
}

# load_board [CONFIG]: hostmot2 + hm2_eth on the simulator, a 1 ms thread with the board's functs.
load_board() {
    rt_start
    halcmd loadrt hostmot2 || exit 1
    halcmd loadrt hm2_eth board_ip="$SIM_IP" ${1:+config="$1"} > "$HM2_TMP/load.out" 2>&1 ||
        { cat "$HM2_TMP/load.out" "$RT_LOG"; exit 1; }
    halcmd loadrt threads name1=servo period1=1000000 || exit 1
    # a loaded test machine is not realtime: generous reply and watchdog times and a high packet error
    # limit, so stalls of other processes cause no false faults (HM2_DEFAULTS=1: keep LinuxCNC's)
    if [ -z "$HM2_DEFAULTS" ]; then
        halcmd setp $BOARD.packet-read-timeout 20000000
        halcmd setp $BOARD.watchdog.timeout_ns 1000000000
        halcmd setp $BOARD.packet-error-limit 1000
    fi
    halcmd addf $BOARD.read-request servo
    halcmd addf $BOARD.read servo
    halcmd addf $BOARD.write servo
}

# wait_until DESCRIPTION COMMAND...: polls COMMAND until it succeeds (at most 30 s); prints the outcome.
wait_until() {
    local what=$1 end=$((SECONDS + 30))
    shift
    until "$@"; do
        if [ $SECONDS -ge $end ]; then echo "timed out: $what"; return 1; fi
        sleep 0.01
    done
    echo "ok: $what"
}

# pin_is PIN VALUE: halcmd getp PIN prints VALUE.
pin_is() {
    [ "$(halcmd getp "$1" 2> /dev/null)" = "$2" ]
}

# near A B TOL: |A - B| <= TOL (floats).
near() {
    awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'
}

# pin_near PIN VALUE TOL: the float pin is within TOL of VALUE.
pin_near() {
    near "$(halcmd getp "$1" 2> /dev/null)" "$2" "$3"
}

# show_items KIND PATTERN: halcmd show KIND without owner ids and addresses.
show_items() {
    case $1 in
    funct) halcmd show funct "$2" | awk 'NR > 2 && NF >= 6 { print $4, $6 }' ;;
    *) halcmd show "$1" "$2" | awk 'NR > 2 && NF >= 5 { $1 = ""; sub(/^ /, ""); print }' ;;
    esac
}

# pins_near PATTERN PIN_A PIN_B TOL: two float pins matched by PATTERN, read in one snapshot, agree.
pins_near() {
    halcmd show pin "$1" | awk -v a="$2" -v b="$3" -v t="$4" '
        $NF == a { va = $(NF - 1); na = 1 } $NF == b { vb = $(NF - 1); nb = 1 }
        END { d = va - vb; if (d < 0) d = -d; exit !(na && nb && d <= t) }'
}

# check DESCRIPTION COMMAND...: prints "ok: ..." or "FAILED: ..." (the expected file needs ok).
check() {
    local what=$1
    shift
    if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; fi
}
