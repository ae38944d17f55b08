#!/bin/bash
# gpio: GPIO outputs (is_output, out, invert_output, is_opendrain) reach the simulated card's pins,
# its pin levels come back on in/in_not, and module outputs wait for the first write to drive.
. ../lib.sh
sim_start --board 7i92
load_board enable_raw
B=$BOARD
io_is() { [ "$(sim_field get io "$1" "$1")" = "$2" ]; }

check "stepgen step pin not driven before the first write" io_is 0 1
halcmd setp $B.gpio.017.is_output 1
halcmd setp $B.gpio.017.out 1
halcmd setp $B.gpio.018.is_output 1
halcmd start
wait_until "stepgen step pin driven (low) after the first write" io_is 0 0
wait_until "gpio 17 drives high" io_is 17 1
wait_until "gpio 18 drives low" io_is 18 0
wait_until "an output's in follows its level" pin_is $B.gpio.017.in TRUE
halcmd setp $B.gpio.017.out 0
wait_until "gpio 17 follows out to low" io_is 17 0
halcmd setp $B.gpio.017.invert_output 1
wait_until "invert_output drives gpio 17 high" io_is 17 1
wait_until "in reads the inverted level" pin_is $B.gpio.017.in TRUE
halcmd setp $B.gpio.017.is_opendrain 1
sim set in 17 0 > /dev/null
wait_until "open drain high is released to the outside level" io_is 17 0
wait_until "in reads the outside level" pin_is $B.gpio.017.in FALSE
halcmd setp $B.gpio.017.out 1
wait_until "open drain low drives low" io_is 17 0
halcmd setp $B.gpio.017.is_output 0
wait_until "is_output FALSE makes it an input again" io_is 17 0
sim set in 17 1 > /dev/null
wait_until "input follows the outside level" pin_is $B.gpio.017.in TRUE

sim set in 20 0 > /dev/null
wait_until "gpio 20 in reads low" pin_is $B.gpio.020.in FALSE
check "gpio 20 in_not is the inverse" pin_is $B.gpio.020.in_not TRUE
sim set in 20 1 > /dev/null
wait_until "gpio 20 in reads high" pin_is $B.gpio.020.in TRUE
check "gpio 20 in_not follows" pin_is $B.gpio.020.in_not FALSE
halcmd setp $B.gpio.000.invert_output 1
wait_until "invert_output of a module pin (stepgen step) inverts it" io_is 0 1
halcmd setp $B.stepgen.00.step.invert_output 0
wait_until "its alias B.stepgen.00.step.invert_output is the same param" io_is 0 0
halcmd setp $B.led.CR01 1
wait_until "LED CR01 is bit 31 of the LED register" sim_answer_is "led 0x80000000" get led

halcmd setp $B.raw.read_address 0x100
wait_until "raw read of the cookie (0x55AACAFE)" pin_is $B.raw.read_data 1437256446
halcmd setp $B.raw.write_address 0x200
halcmd setp $B.raw.write_data 0x40000000
halcmd setp $B.raw.write_strobe 1
wait_until "raw write reaches the card (LED register)" sim_answer_is "led 0x40000000" get led
check "write_strobe resets itself" pin_is $B.raw.write_strobe FALSE
