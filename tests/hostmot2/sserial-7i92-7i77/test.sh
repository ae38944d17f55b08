#!/bin/bash
# sserial-7i92-7i77: a 7I92 with a 7I77 on Smart Serial channels 0 (field I/O, mode 3) and 1
# (analog servo outputs): LinuxCNC's names, analog outputs scaled to the DACs, MPG encoder counts.
. ../lib.sh
sim_start --board 7i92-7i77
load_board "sserial_port_0=30"
R0=$BOARD.7i77.0.0
R1=$BOARD.7i77.0.1
grep -E "^Board " "$RT_LOG"
echo "channel 0 pins:"
show_items pin "$R0." | awk '{ print $1, $2, $NF }' | grep -Ev -- '-(0[2-9]|1[0-9]|2[0-9]|3[01])(-not)?$'
echo "channel 1 pins:"
show_items pin "$R1." | awk '{ print $1, $2, $NF }'
echo "channel 1 params:"
show_items param "$R1." | awk '{ print $1, $2, $(NF - 1), $NF }'
halcmd start
wait_until "channel 1 runs" sim_is running 1 get sserial 1
halcmd setp $R1.analogena 1
halcmd setp $R1.analogout2 5
wait_until "analogout2 5 V is half of the 13-bit DAC range (2048)" sim_is analogout2 2048 get sserial 1
check "analogena reaches the 7I77" sim_is analogena 1 get sserial 1
halcmd setp $R1.analogout2 -12
wait_until "analogout2 -12 V clamps at -10 V (-4095 as 13 bits: 4097)" sim_is analogout2 4097 get sserial 1
halcmd setp $R1.analogout2-minlim -5
wait_until "a raised minlim limits it to -5 V (-2048 as 13 bits: 6144)" sim_is analogout2 6144 get sserial 1
sim set sserial 0 encoder0 10 > /dev/null
wait_until "MPG encoder0 counts 10" pin_is $R0.encoder0.count 10
sim set sserial 0 encoder0 250 > /dev/null
wait_until "and -16 across the 8-bit wrap (-6)" pin_is $R0.encoder0.count -6
sim set sserial 0 fieldvoltage 170 > /dev/null
wait_until "fieldvoltage 170/255 of 36.3 V (24.2)" pin_near $R0.fieldvoltage 24.2 0.01
sim set sserial 0 input-31 1 > /dev/null
wait_until "input-31 reaches HAL" pin_is $R0.input-31 TRUE
halcmd setp $R0.output-07 1
wait_until "output-07 reaches the 7I77" sim_is output 0x80 get sserial 0
