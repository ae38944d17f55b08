#!/bin/bash
# sserial-config: sserial_port_0= strings: x disables a channel (its pins stay GPIO, no remote
# objects), a second remote on channel 1 gets its own names, and bad strings or a mode the remote
# lacks fail the load with a message naming the board and what is wrong.
. ../lib.sh
BOARD=hm2_7i76e.0
sim_start --board 7i76e --remote 1:7i76
rt_start
halcmd loadrt hostmot2 || exit 1
try() {
    local before
    before=$(wc -l < "$RT_LOG")
    if halcmd loadrt hm2_eth board_ip=$SIM_IP config="$1" > /dev/null 2>&1; then echo "LOADED: $1"; halcmd unloadrt hm2_eth; fi
    tail -n +"$((before + 1))" "$RT_LOG" | grep -E "sserial|Smart Serial|fails" | sed "s/$SIM_IP/BOARD_IP/g"
}
try "sserial_port_0=0a"
try "sserial_port_0=000000000"
try "sserial_port_0=7"
try "sserial_port_0=x9"
halcmd loadrt hm2_eth board_ip=$SIM_IP config="sserial_port_0=x0" > /dev/null 2>&1 || { echo "x0 did not load"; exit 1; }
echo "remotes with x0: $(halcmd list pin "$BOARD.7i76.*.output-00")"
echo "channel 0 GPIO outputs: $(halcmd list pin "$BOARD.gpio.04[4-6].out")"
halcmd unloadrt hm2_eth
halcmd loadrt hm2_eth board_ip=$SIM_IP config="sserial_port_0=xx" > /dev/null 2>&1 || { echo "xx did not load"; exit 1; }
echo "Smart Serial objects with xx: [$(halcmd list pin "$BOARD.sserial.*") $(halcmd list pin "$BOARD.7i76.*")]"
halcmd unloadrt hm2_eth
halcmd loadrt hm2_eth board_ip=$SIM_IP config="sserial_port_0=02" > /dev/null 2>&1 || { echo "02 did not load"; exit 1; }
echo "remotes with 02: $(halcmd list pin "$BOARD.7i76.*.output-00")"
echo "channel 1 mode 2 MPG encoder: $(halcmd list pin "$BOARD.7i76.0.1.encoder0.*")"
echo "fieldvoltage only in mode 2: $(halcmd list pin "$BOARD.7i76.*.fieldvoltage")"
halcmd unloadrt hm2_eth
halcmd unloadrt hostmot2
halcmd loadrt hostmot2 use_serial_numbers=1 sserial_baudrate=115200 || exit 1
halcmd loadrt hm2_eth board_ip=$SIM_IP > /dev/null 2>&1 || { echo "use_serial_numbers did not load"; exit 1; }
echo "use_serial_numbers=1: $(halcmd list pin "hm2_7i76.*.output-00")"
grep -o "sserial_baudrate=.*" "$RT_LOG"
