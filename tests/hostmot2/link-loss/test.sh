#!/bin/bash
# link-loss: a board that stops answering puts hm2 in io_error (reported once, naming the board) and,
# without pets, the card's watchdog drives every output safe; clearing io_error and has_bit recovers.
# A card that disappears (connection refused) and comes back is recovered by the same steps.
. ../lib.sh
sim_start --board 7i92
load_board
B=$BOARD
io_is() { [ "$(sim_field get io "$1" "$1")" = "$2" ]; }
halcmd setp $B.packet-error-limit 10
halcmd setp $B.gpio.017.is_output 1
halcmd setp $B.gpio.017.out 1
sim set in 17 0 > /dev/null
halcmd start
wait_until "gpio 17 driven high" io_is 17 1

sim pause > /dev/null
wait_until "lost replies end in io_error" pin_is $B.io_error TRUE
check "packet-error-exceeded is set" pin_is $B.packet-error-exceeded TRUE
check "packet-error-level is at the limit" pin_is $B.packet-error-level 10
check "each lost reply is logged" rt_log_has "hm2_eth: receive_queued_reads: error (Resource temporarily unavailable) after"
wait_until "without pets the card's watchdog bites" sim_said bite
check "gpio 17 is released (safe)" io_is 17 0
sleep 0.3
check "io_error is reported once, naming the board" \
    [ "$(grep -c '^hm2/hm2_7i92.0: error finishing read! iter=' "$RT_LOG")" = 1 ]
check "no datagrams while in io_error" [ "$(sim_field stats rx)" = "$(sleep 0.2; sim_field stats rx)" ]

sim resume > /dev/null
halcmd setp $B.io_error 0
wait_until "cleared io_error: the bite is seen" pin_is $B.watchdog.has_bit TRUE
check "packet-error-level restarts at 0" pin_is $B.packet-error-level 0
check "outputs stay safe until has_bit is cleared" io_is 17 0
halcmd setp $B.watchdog.has_bit 0
wait_until "gpio 17 driven high again" io_is 17 1

sim_stop
wait_until "a vanished card ends in io_error too" pin_is $B.io_error TRUE
check "connection refused is logged" rt_log_has "Connection refused"
sim_start --board 7i92
halcmd setp $B.io_error 0
wait_until "a restarted card gets its configuration again" io_is 17 1
check "and stays out of io_error" pin_is $B.io_error FALSE
