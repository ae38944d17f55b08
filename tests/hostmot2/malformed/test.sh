#!/bin/bash
# malformed: dropped, short and stale replies are soft errors (counted, skipped, configuration
# rewritten); below the limit the board keeps working, at the limit it goes to io_error.
. ../lib.sh
sim_start --board 7i92
load_board
B=$BOARD
io_is() { [ "$(sim_field get io "$1" "$1")" = "$2" ]; }
total() { halcmd getp $B.packet-error-total; }
total_at_least() { [ "$(total)" -ge "$1" ]; }
halcmd setp $B.packet-error-limit 10
halcmd setp $B.gpio.017.is_output 1
halcmd setp $B.gpio.017.out 1
halcmd start
wait_until "gpio 17 driven high" io_is 17 1

base=$(total)
sim drop 3 > /dev/null
wait_until "3 dropped replies are counted" total_at_least $((base + 3))
base=$(total)
sim garble 2 > /dev/null
wait_until "2 short replies are counted" total_at_least $((base + 2))
base=$(total)
sim stale 2 > /dev/null
wait_until "2 replies with a wrong sequence echo are counted" total_at_least $((base + 2))
wait_until "the level decays back to 0" pin_is $B.packet-error-level 0
check "no io_error below the limit" pin_is $B.io_error FALSE
check "packet-error is clear again" pin_is $B.packet-error FALSE
halcmd setp $B.gpio.017.out 0
wait_until "the board still works" io_is 17 0

halcmd setp $B.packet-error-limit 4
sim drop 2 > /dev/null
wait_until "at the limit (2 x increment 2) the board goes to io_error" pin_is $B.io_error TRUE
check "packet-error-exceeded set" pin_is $B.packet-error-exceeded TRUE
halcmd setp $B.io_error 0
wait_until "clearing io_error resumes" pin_is $B.packet-error-exceeded FALSE
halcmd setp $B.gpio.017.out 1
wait_until "the board works again" io_is 17 1
