#!/bin/bash
# two-boards: two cards of the same type are hm2_7i92.0 and hm2_7i92.1 in board_ip order, each with
# its own config string; both read-requests go first and both boards run in one thread.
. ../lib.sh
IP2=127.$((20 + INST / 250)).$((INST % 250)).2
sim_start --board 7i92
mkfifo "$HM2_TMP/sim2.in"
mesa-sim --ip "$IP2" --board 7i92 < "$HM2_TMP/sim2.in" > "$HM2_TMP/sim2b.out" 2>&1 &
SIM2=$!
exec 4> "$HM2_TMP/sim2.in"
trap 'echo quit >&4; exec 4>&-; wait $SIM2; hm2_cleanup' EXIT
for i in $(seq 500); do grep -q '^ready' "$HM2_TMP/sim2b.out" && break; sleep 0.01; done
rt_start
halcmd loadrt hostmot2
halcmd loadrt hm2_eth board_ip=$SIM_IP,$IP2 config="num_stepgens=1,num_stepgens=2" || { cat "$RT_LOG"; exit 1; }
halcmd loadrt threads name1=servo period1=1000000
for b in 0 1; do halcmd setp hm2_7i92.$b.packet-read-timeout 20000000; halcmd setp hm2_7i92.$b.packet-error-limit 1000; done
halcmd addf hm2_7i92.0.read-request servo
halcmd addf hm2_7i92.1.read-request servo
halcmd addf hm2_7i92.0.read servo
halcmd addf hm2_7i92.1.read servo
halcmd addf hm2_7i92.0.write servo
halcmd addf hm2_7i92.1.write servo
grep -E "discovered|registered" "$RT_LOG"
echo "board 0 stepgens: $(halcmd list pin 'hm2_7i92.0.stepgen.*.enable')"
echo "board 1 stepgens: $(halcmd list pin 'hm2_7i92.1.stepgen.*.enable')"
halcmd setp hm2_7i92.0.gpio.017.is_output 1
halcmd setp hm2_7i92.0.gpio.017.out 1
halcmd setp hm2_7i92.1.gpio.018.is_output 1
halcmd setp hm2_7i92.1.gpio.018.out 1
halcmd start
# sim2 CMD...: a command to the second card and its answer line.
sim2() {
    local before end=$((SECONDS + 5))
    before=$(wc -l < "$HM2_TMP/sim2b.out")
    echo "$*" >&4
    until [ "$(wc -l < "$HM2_TMP/sim2b.out")" -gt "$before" ]; do
        [ $SECONDS -ge $end ] && { echo "sim2: no answer to '$*'"; return 1; }
        sleep 0.01
    done
    tail -n +"$((before + 1))" "$HM2_TMP/sim2b.out" | head -n 1
}
io2_is() { [ "$(sim2 get io "$1")" = "io $1 $2" ]; }
wait_until "card 1 drives its gpio 17" sim_is 17 1 get io 17
wait_until "card 2 drives its gpio 18" io2_is 18 1
sim set in 18 0 > /dev/null
sim2 set in 17 0 > /dev/null
check "card 1's gpio 18 is an input" sim_is 18 0 get io 18
check "card 2's gpio 17 is an input" io2_is 17 0
wait_until "card 1's input reaches hm2_7i92.0" pin_is hm2_7i92.0.gpio.018.in FALSE
check "and not hm2_7i92.1" pin_is hm2_7i92.1.gpio.018.in TRUE
