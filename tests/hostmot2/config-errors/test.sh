#!/bin/bash
# config-errors: bad config= strings, bad module arguments and unreachable boards fail the load with
# LinuxCNC's messages and leave nothing behind; partial module counts leave the rest of the pins GPIO.
. ../lib.sh
sim_start --board 7i92
rt_start
halcmd loadrt hostmot2 || exit 1

# try ARGS...: one hm2_eth load that must fail; prints its new driver log lines (board address hidden).
try() {
    local before
    before=$(wc -l < "$RT_LOG")
    if halcmd loadrt hm2_eth "$@" > /dev/null 2>&1; then echo "LOADED: $*"; halcmd unloadrt hm2_eth; fi
    tail -n +"$((before + 1))" "$RT_LOG" | grep -E 'ERROR|error|invalid|only|fails|failed|Unknown|sserial|not an' |
        grep -v SIOCSARP | sed -e "s/$SIM_IP/BOARD_IP/g" -e "s/127\.[0-9]*\.[0-9]*\.2/NO_BOARD_IP/g"
    echo "hm2_eth left: [$(halcmd list comp hm2_eth)]"
}
try board_ip=$SIM_IP config="num_stepgens=9"
try board_ip=$SIM_IP config="num_encoders=1 bogus=1"
try board_ip=$SIM_IP config="sserial_port_7=000"
halcmd loadrt hm2_eth board_ip=$SIM_IP config="firmware=hm2/7i92/an_image_name_of_more_than_30_chars.bit" && echo "firmware= is ignored by hm2_eth" && halcmd unloadrt hm2_eth
try board_ip=127.$((20 + INST / 250)).$((INST % 250)).2
try board_ip=no.such.address
try board_ip=$SIM_IP board_rtnet=evl
try board_ip=$SIM_IP board_rtnet=xenomai
halcmd loadrt hm2_eth board_ip=$SIM_IP board_mac=00:11:22:33:44:55 2>&1 | grep -o "Unknown parameter.*"

before=$(wc -l < "$RT_LOG")
halcmd loadrt hm2_eth board_ip=$SIM_IP firewall=bogus config="num_stepgens=1 stepgen_width=1 num_encoders=0 num_pwmgens=0" || exit 1
tail -n +"$((before + 1))" "$RT_LOG" | grep -E "firewall backend|IO Pin 00[0-3]|IO Pin 01[4-6]"
echo "stepgens: $(halcmd list pin 'hm2_7i92.0.stepgen.*.enable')"
echo "encoders: [$(halcmd list pin 'hm2_7i92.0.encoder.*')]"
echo "gpio 001 (stepgen 0 direction beyond stepgen_width=1): $(halcmd list pin 'hm2_7i92.0.gpio.001.*')"
echo "gpio 002 (stepgen 1 step, disabled): $(halcmd list pin 'hm2_7i92.0.gpio.002.*')"
echo "gpio 002 params: $(halcmd list param 'hm2_7i92.0.gpio.002.*')"
