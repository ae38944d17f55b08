#!/bin/bash
# sserial-7i76e: the 7I76E's on-board 7I76 (Smart Serial port 0, channel 0) is discovered with
# LinuxCNC's names; outputs, spindle and params reach the twin, inputs and analog come back.
. ../lib.sh
BOARD=hm2_7i76e.0
sim_start --board 7i76e
load_board "sserial_port_0=10"
R=$BOARD.7i76.0.0
cat "$HM2_TMP/load.out" "$RT_LOG" | grep -E "Smart Serial Firmware|^Board |IO Pin 04[4-9]"
echo "pins:"
show_items pin "$R." | awk '{ print $1, $2, $NF }' | grep -Ev -- '-(0[2-9]|1[0-9]|2[0-9]|3[01])(-not)?$'
echo "params:"
show_items param "$R." | awk '{ print $1, $2, $(NF - 1), $NF }' | grep -Ev -- '-(0[2-9]|1[0-9])-invert$'
echo "port:"
show_items pin "$BOARD.sserial." | awk '{ print $1, $2, $NF }'
show_items param "$BOARD.sserial." | awk '{ print $1, $2, $(NF - 1), $NF }'
echo "GPIO outputs among IO 044..049 (channel 1 is empty): $(halcmd list pin "$BOARD.gpio.04[4-9].out")"
halcmd start
field() { sim_field get sserial 0 "$1"; }
wait_until "the remote runs in mode 1" sim_is mode 1 get sserial 0
halcmd setp $R.output-00 1
halcmd setp $R.output-03 1
halcmd setp $R.output-15-invert 1
wait_until "outputs 0, 3 and inverted 15 reach the 7I76" sim_is output 0x8009 get sserial 0
halcmd setp $R.spinena 1
halcmd setp $R.spindir 1
halcmd setp $R.spinout 50
wait_until "spinena reaches the 7I76" sim_is spinena 1 get sserial 0
check "spindir reaches the 7I76" sim_is spindir 1 get sserial 0
check "spinout 50 of scalemax 100 is half scale (32768)" sim_is spinout 32768 get sserial 0
halcmd setp $R.spinout 250
wait_until "spinout clamps at maxlim (65535)" sim_is spinout 65535 get sserial 0
sim set sserial 0 input-05 1 > /dev/null
wait_until "input-05 reaches HAL" pin_is $R.input-05 TRUE
check "input-05-not is its inverse" pin_is $R.input-05-not FALSE
check "input-04 stays low" pin_is $R.input-04 FALSE
sim set sserial 0 analogin2 255 > /dev/null
wait_until "analogin2 at full scale reads 36.3 V" pin_near $R.analogin2 36.3 0.01
sim set sserial 0 analogin2 128 > /dev/null
wait_until "analogin2 at 128/255 reads 18.2 V" pin_near $R.analogin2 18.22 0.01
check "no faults while running" pin_is $BOARD.sserial.port-0.fault-count 0
check "remote fault pin FALSE" pin_is $R.fault FALSE
halcmd setp $BOARD.sserial.port-0.run 0
wait_until "run FALSE stops the port (state 0)" pin_is $BOARD.sserial.port-0.port_state 0
wait_until "the stopped remote drops its outputs (watchdog)" sim_is outputs-enabled 0 get sserial 0
halcmd setp $R.nvwatchdogtimeout 100
wait_until "a global written while stopped reaches the remote" sim_is nvwatchdogtimeout 100 get sserial 0
halcmd setp $BOARD.sserial.port-0.run 1
wait_until "run TRUE restarts the port (state 3)" pin_is $BOARD.sserial.port-0.port_state 3
wait_until "outputs come back after the restart" sim_is output 0x8009 get sserial 0
